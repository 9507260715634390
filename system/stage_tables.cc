#include "system/stage_tables.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

namespace servodrift::system
{
  namespace
  {
    /// What the valve model divides by must not vanish: a table that passes the reader's format
    /// checks (an edited or foreign file) can still describe a valve that cannot be commanded or
    /// held. Refused here, naming the file, rather than as a non-finite result later.
    void check_physical(const Table &t, const std::string &file)
    {
      const auto refuse = [&](double T, const std::string &what) {
        throw InputError(file + ": at " + format_number(T) + " degC " + what +
                         " (a table from another tool or edited by hand? re-run its stage)");
      };
      const std::size_t T = 0;
      if (t.name() == "torque_motor")
        {
          // the command acts through dT_em/di (K_t): the torque must change with the current
          const std::size_t angle = t.column_index("angle"), torque = t.column_index("torque");
          // the valve at rest, the nulling and the null shift are at i = 0
          const std::vector<double> currents = t.column("current");
          const auto [low, high] = std::minmax_element(currents.begin(), currents.end());
          if (!currents.empty() && !(*low <= 0 && *high >= 0))
            throw InputError(file + ": its currents span " + format_number(*low) + " to " + format_number(*high) +
                             " A without 0, where the valve at rest, the nulling and the null shift are "
                             "(`Sweeps/Motor currents' must span 0; re-run the magnetics stage)");
          std::map<std::pair<double, double>, std::pair<double, double>> range; // (T, theta) -> min, max
          for (const auto &r : t.rows)
            {
              const auto [it, fresh] = range.try_emplace({r[T], r[angle]}, r[torque], r[torque]);
              if (!fresh)
                it->second = {std::min(it->second.first, r[torque]), std::max(it->second.second, r[torque])};
            }
          for (const auto &[point, minmax] : range)
            if (!(minmax.second > minmax.first))
              refuse(point.first, "and " + format_number(point.second) +
                                    " rad the torque does not change with the current: the valve cannot be commanded");
        }
      else if (t.name() == "spring_tube")
        {
          const std::size_t k = t.column_index("stiffness");
          for (const auto &r : t.rows)
            if (!(r[k] > 0))
              refuse(r[T], "the stiffness is " + format_number(r[k]) + " N*m/rad; it must be > 0");
        }
      else if (t.name() == "fixed_orifice_bore" || t.name() == "nozzle_flapper_bore")
        {
          const std::size_t step = t.column_index("bore_step"), q = t.column_index("flow_ratio");
          const bool nozzle = t.name() == "nozzle_flapper_bore";
          if (t.rows.empty())
            throw InputError(file + ": no rows (re-run the flow stage)");
          for (const auto &r : t.rows)
            if (!(r[step] != 0 && r[q] > 0 && (!nozzle || r[t.column_index("force_ratio")] > 0)))
              refuse(r[T], "a bore step of 0 or a ratio <= 0 (flow_ratio " + format_number(r[q]) + ")");
        }
      else
        {
          const std::size_t dp = t.column_index("pressure_difference"), q = t.column_index("flow_rate");
          for (const auto &r : t.rows)
            if (r[dp] > 0 && (!(r[q] >= 0) || (t.name() == "fixed_orifice" && !(r[q] > 0))))
              refuse(r[T], "the flow rate at dp = " + format_number(r[dp]) + " Pa is " + format_number(r[q]) +
                             " m^3/s; it must be > 0 for a pressure difference > 0");
        }
    }
  } // namespace

  StageTables StageTables::read(const std::string &directory, const ValveDescription &valve)
  {
    StageTables t;
    t.torque_motor = Table::read(directory + "/torque_motor.csv", "torque_motor");
    t.spring_tube = Table::read(directory + "/spring_tube.csv", "spring_tube");
    t.fixed_orifice = Table::read(directory + "/fixed_orifice.csv", "fixed_orifice");
    t.nozzle_flapper = Table::read(directory + "/nozzle_flapper.csv", "nozzle_flapper");
    for (const auto &[name, bore] : {std::make_pair("fixed_orifice_bore", &t.fixed_orifice_bore),
                                     std::make_pair("nozzle_flapper_bore", &t.nozzle_flapper_bore)})
      if (std::filesystem::exists(directory + "/" + name + ".csv"))
        *bore = Table::read(directory + "/" + name + ".csv", name);
    std::vector<const Table *> all = {&t.torque_motor, &t.spring_tube, &t.fixed_orifice, &t.nozzle_flapper};
    for (const auto *bore : {&t.fixed_orifice_bore, &t.nozzle_flapper_bore})
      if (*bore)
        all.push_back(&**bore);
    for (const Table *table : all)
      check_physical(*table, directory + "/" + table->name() + ".csv");
    for (const Table *table : all)
      if (table->parameters_sha256 != valve.parameters_sha256)
        t.warnings.push_back("tables/" + table->name() + ".csv was made with other parameters (sha256 " +
                             table->parameters_sha256.substr(0, 12) + ", this run " +
                             valve.parameters_sha256.substr(0, 12) + "); its numbers come from that valve description");
    for (const Table *table : {&t.torque_motor, &t.spring_tube, &t.fixed_orifice, &t.nozzle_flapper})
      {
        std::size_t not_converged = 0, beyond_verified = 0, time_averaged = 0, field_reference = 0;
        for (const auto &row : table->rows)
          {
            not_converged += row.back() == flags::not_converged;
            beyond_verified += row.back() == flags::beyond_verified;
            time_averaged += row.back() == flags::time_averaged;
            field_reference += row.back() == flags::field_reference;
          }
        for (const auto &note : table->notes) // the mesh's discretisation error, the unconverged cases
          t.notes.push_back("tables/" + table->name() + ".csv: " + note);
        if (field_reference > 0)
          t.notes.push_back("tables/" + table->name() + ".csv: " + std::to_string(field_reference) + " of " +
                            std::to_string(table->rows.size()) +
                            " rows are creeping flows where the reduced-order closed forms leave their range (flag "
                            "6): the field level, verified against the creeping limit, is the reference there");
        if (not_converged > 0)
          t.warnings.push_back("tables/" + table->name() + ".csv: " + std::to_string(not_converged) + " of " +
                               std::to_string(table->rows.size()) +
                               " rows did not converge at the field level (flag 2): the reduced-order value stands in; "
                               "the table's notes below name each case, its nearest state's residual and its fields");
        if (time_averaged > 0)
          t.warnings.push_back("tables/" + table->name() + ".csv: " + std::to_string(time_averaged) + " of " +
                               std::to_string(table->rows.size()) +
                               " rows have no steady solution at the field level (flag 5): they carry the time "
                               "average, its spread in flow/" + table->name() + "_time_averages.csv");
        if (beyond_verified > 0)
          t.warnings.push_back("tables/" + table->name() + ".csv: " + std::to_string(beyond_verified) + " of " +
                               std::to_string(table->rows.size()) +
                               " rows lie beyond the range where the field level was verified (flag 4: the field "
                               "and reduced-order discharge coefficients differ by more than the factor stated in "
                               "flow/" + table->name() + "_cases.csv)");
      }
    return t;
  }

  StageTables StageTables::with_pilot_variant(const std::string &directory, const std::string &variant) const
  {
    StageTables t = *this;
    t.warnings.clear();
    t.fixed_orifice = Table::read(directory + "/fixed_orifice." + variant + ".csv", "fixed_orifice");
    t.nozzle_flapper = Table::read(directory + "/nozzle_flapper." + variant + ".csv", "nozzle_flapper");
    for (const Table *table : {&t.fixed_orifice, &t.nozzle_flapper})
      check_physical(*table, directory + "/" + table->name() + "." + variant + ".csv");
    return t;
  }

  namespace
  {
    /// Q/sqrt(dp): smooth in dp where Q ~ sqrt(dp) is not; 0 in the laminar limit dp -> 0.
    std::function<double(const std::vector<double> &)> conductance(const Table &t)
    {
      const std::size_t q = t.column_index("flow_rate"), dp = t.column_index("pressure_difference");
      return [q, dp](const std::vector<double> &r) { return r[dp] > 0 ? r[q] / std::sqrt(r[dp]) : 0.0; };
    }
  } // namespace

  StageFunctions::StageFunctions(const StageTables &t)
    : torque(GridFunction::from_table(t.torque_motor, "table torque_motor", "torque"))
    , stiffness(GridFunction::from_table(t.spring_tube, "table spring_tube", "stiffness"))
    , orifice_conductance(GridFunction::from_table(t.fixed_orifice, "table fixed_orifice", conductance(t.fixed_orifice)))
    , orifice_discharge(GridFunction::from_table(t.fixed_orifice, "table fixed_orifice", "discharge_coefficient"))
    , nozzle_conductance(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", conductance(t.nozzle_flapper)))
    , nozzle_discharge(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", "discharge_coefficient"))
    , flapper_force(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", "flapper_force"))
  {
    const auto log_of = [](const Table &table, const std::string &column) {
      const std::size_t c = table.column_index(column);
      return GridFunction::from_table(table, "table " + table.name(),
                                      [c](const std::vector<double> &row) { return std::log(row[c]); });
    };
    if (t.fixed_orifice_bore)
      orifice_bore = BoreSensitivity{log_of(*t.fixed_orifice_bore, "flow_ratio"), std::nullopt,
                                     t.fixed_orifice_bore->rows.front()[t.fixed_orifice_bore->column_index("bore_step")]};
    if (t.nozzle_flapper_bore)
      nozzle_bore = BoreSensitivity{log_of(*t.nozzle_flapper_bore, "flow_ratio"),
                                    log_of(*t.nozzle_flapper_bore, "force_ratio"),
                                    t.nozzle_flapper_bore->rows.front()[t.nozzle_flapper_bore->column_index("bore_step")]};
  }
} // namespace servodrift::system
