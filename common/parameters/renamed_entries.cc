#include "common/parameters/renamed_entries.h"

#include <algorithm>

namespace servodrift
{
  namespace
  {
    /// The entry of `list' whose `key' is `path', or nullptr.
    template <typename Entry>
    const Entry *find_entry(const std::vector<Entry> &list, std::string Entry::*key, const std::string &path)
    {
      const auto found = std::find_if(list.begin(), list.end(), [&](const Entry &e) { return e.*key == path; });
      return found == list.end() ? nullptr : &*found;
    }
  } // namespace

  const std::vector<RenamedEntry> &renamed_entries()
  {
    // "Pilot stage" split by concern: the reduced order's laws, the field level's mesh, its
    // solution and its time average, the bore tables
    static const std::vector<RenamedEntry> list = {
      {"Pilot stage/Nozzle discharge coefficient", "Pilot stage/Reduced order/Nozzle discharge coefficient"},
      {"Pilot stage/Fixed orifice law", "Pilot stage/Reduced order/Fixed orifice law"},
      {"Pilot stage/Nozzle law", "Pilot stage/Reduced order/Nozzle law"},
      {"Pilot stage/Flapper force law", "Pilot stage/Reduced order/Flapper force law"},
      {"Pilot stage/Field mesh resolution", "Pilot stage/Field mesh/Resolution"},
      {"Pilot stage/Field grid sequencing", "Pilot stage/Field mesh/Grid sequencing"},
      {"Pilot stage/Field plenum size", "Pilot stage/Field mesh/Plenum size"},
      {"Pilot stage/Field chamber length", "Pilot stage/Field mesh/Chamber length"},
      {"Pilot stage/Field outlet radius", "Pilot stage/Field mesh/Outlet radius"},
      {"Pilot stage/Fixed orifice flow model", "Pilot stage/Field solution/Fixed orifice flow model"},
      {"Pilot stage/Fixed orifice transition Reynolds number",
       "Pilot stage/Field solution/Fixed orifice transition Reynolds number"},
      {"Pilot stage/Nozzle flow model", "Pilot stage/Field solution/Nozzle flow model"},
      {"Pilot stage/Nozzle transition Reynolds number", "Pilot stage/Field solution/Nozzle transition Reynolds number"},
      {"Pilot stage/Field cavitation", "Pilot stage/Field solution/Cavitation"},
      {"Pilot stage/Field continuation ratio", "Pilot stage/Field solution/Continuation ratio"},
      {"Pilot stage/Field turbulent viscosity limit", "Pilot stage/Field solution/Turbulent viscosity limit"},
      {"Pilot stage/Nozzle stall window", "Pilot stage/Field solution/Nozzle stall window"},
      {"Pilot stage/Model-form alternatives", "Pilot stage/Field solution/Model-form alternatives"},
      {"Pilot stage/Field time average", "Pilot stage/Time average/Enabled"},
      {"Pilot stage/Field time step Courant number", "Pilot stage/Time average/Courant number"},
      {"Pilot stage/Field time step iterations", "Pilot stage/Time average/Step iterations"},
      {"Pilot stage/Field time step halvings", "Pilot stage/Time average/Step halvings"},
      {"Pilot stage/Field time steps", "Pilot stage/Time average/Steps"},
      {"Pilot stage/Field time steps limit", "Pilot stage/Time average/Steps limit"},
      {"Pilot stage/Field averaged fraction", "Pilot stage/Time average/Averaged fraction"},
      {"Pilot stage/Field time average uncertainty limit", "Pilot stage/Time average/Uncertainty limit"},
      {"Pilot stage/Bore sensitivity", "Pilot stage/Bore sensitivity/Tables"},
      {"Pilot stage/Bore sensitivity step", "Pilot stage/Bore sensitivity/Step"},
    };
    return list;
  }

  const RenamedEntry *renamed_entry(const std::string &path)
  {
    return find_entry(renamed_entries(), &RenamedEntry::old_path, path);
  }

  const std::vector<RetiredEntry> &retired_entries()
  {
    static const std::vector<RetiredEntry> list = {
      {"Torque motor/Virtual work step",
       "the field level's torque_error is now the change from a mesh of half the resolution, and virtual work, "
       "which checks the stress tensor, is a verification with its own step"},
    };
    return list;
  }

  const RetiredEntry *retired_entry(const std::string &path)
  {
    return find_entry(retired_entries(), &RetiredEntry::path, path);
  }

  std::string retirement_warning(const std::string &where, const RetiredEntry &entry)
  {
    return "servodrift: warning: " + where + ": `" + entry.path + "' is no longer read (" + entry.why + "); ignored";
  }

  std::string deprecation_warning(const std::string &where, const RenamedEntry &entry)
  {
    return "servodrift: warning: " + where + ": `" + entry.old_path + "' is deprecated; it is now `" +
           entry.new_path + "' (read as such)";
  }
} // namespace servodrift
