#include "fmu/export_fmu.h"

#include "common/error.h"
#include "common/output_files.h"
#include "common/provenance.h"
#include "common/stage_output.h"
#include "common/version.h"
#include "fmu/fmu_variables.h"
#include "fmu/model_description.h"
#include "system/stage_tables.h"

#include <minizip/zip.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace servodrift::fmu
{
  namespace
  {
    using Entries = std::vector<std::pair<std::string, std::string>>; ///< archive path, bytes

    /// Writes the entries as a zip archive through a temporary file and the run's transaction.
    void write_zip(const std::string &path, const Entries &entries)
    {
      const std::string temporary = temporary_beside(path);
      zipFile zip = zipOpen64(temporary.c_str(), APPEND_STATUS_CREATE);
      if (!zip)
        throw InputError(temporary + ": cannot be written");
      bool ok = true;
      for (const auto &[name, bytes] : entries)
        {
          zip_fileinfo info{};
          ok = ok &&
               zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED,
                                     Z_DEFAULT_COMPRESSION, bytes.size() >= 0xffffffffu) == ZIP_OK &&
               zipWriteInFileInZip(zip, bytes.data(), static_cast<unsigned int>(bytes.size())) == ZIP_OK &&
               zipCloseFileInZip(zip) == ZIP_OK;
        }
      ok = zipClose(zip, nullptr) == ZIP_OK && ok;
      if (!ok)
        {
          std::filesystem::remove(temporary);
          throw InputError(path + ": the archive could not be written");
        }
      install_file(temporary, path);
    }

    std::string guid_of(const Entries &entries)
    {
      std::string all;
      for (const auto &[name, bytes] : entries)
        all += name + '\0' + sha256_hex(bytes);
      const std::string h = sha256_hex(all);
      return "{" + h.substr(0, 8) + "-" + h.substr(8, 4) + "-" + h.substr(12, 4) + "-" + h.substr(16, 4) + "-" +
             h.substr(20, 12) + "}";
    }

    std::string utc_now()
    {
      const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
      std::tm tm{};
      gmtime_r(&t, &tm);
      char text[32];
      std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &tm);
      return text;
    }

    std::string html_escaped(const std::string &text)
    {
      std::string out;
      for (char c : text)
        out += c == '<'   ? std::string("&lt;")
               : c == '>' ? std::string("&gt;")
               : c == '&' ? std::string("&amp;")
                          : std::string(1, c);
      return out;
    }

    std::string documentation(const Layout &layout, const std::string &provenance)
    {
      std::ostringstream s;
      s << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>servodrift_valve</title></head><body>\n"
        << "<h1>servodrift_valve: a double-nozzle-flapper pressure servo valve</h1>\n"
        << "<p>The valve of <code>servodrift dynamics</code> (model.md E29-E37, the asymmetry of the described "
           "valve) with its coefficient tables as functions of temperature. FMI 2.0, Model Exchange "
           "(event-free: the contacts and stops are smooth laws) and Co-Simulation (CVODE inside, inputs held "
           "over a step). It starts at the static operating point of its start inputs. Replacing a table or "
           "<code>parameters.prm</code> in <code>resources/</code> changes the model. The user guide "
           "(doc/user-guide.md, section FMU) says how to use it in Simulink, Amesim, Hopsan, OpenModelica and "
           "Dymola.</p>\n<h2>Variables</h2>\n<table border=\"1\">\n"
        << "<tr><th>name</th><th>kind</th><th>unit</th><th>start</th><th>min</th><th>max</th><th>what it "
           "is</th></tr>\n";
      const char *kinds[] = {"state", "derivative", "input", "output", "parameter"};
      const auto cell = [](const std::optional<double> &v) { return v ? format_cell(*v) : std::string(); };
      for (const auto &v : layout.variables)
        s << "<tr><td><code>" << html_escaped(v.name) << "</code></td><td>" << kinds[static_cast<int>(v.role)]
          << "</td><td>" << v.unit << (v.display_unit.empty() ? "" : " (shown in " + v.display_unit + ")")
          << "</td><td>" << (v.boolean ? std::string(v.start && *v.start ? "true" : "false") : cell(v.start))
          << "</td><td>" << cell(v.min) << "</td><td>" << cell(v.max) << "</td><td>" << html_escaped(v.description)
          << "</td></tr>\n";
      s << "</table>\n<h2>How the tables were made</h2>\n<pre>" << html_escaped(provenance) << "</pre>\n"
        << "</body></html>\n";
      return s.str();
    }
  } // namespace

  std::string fmu_library()
  {
    std::error_code error;
    const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::string path = (program.parent_path() / "servodrift_valve.so").string();
    if (error || !std::filesystem::is_regular_file(path))
      throw InputError("the FMU's binary servodrift_valve.so is not beside the program (" + path +
                       "): build the target servodrift_valve_fmu");
    return path;
  }

  ExportedFmu export_fmu(const ValveDescription &valve)
  {
    const std::string tables_dir = tables_directory(valve);
    if (!std::filesystem::exists(tables_dir + "/torque_motor.csv"))
      throw InputError(tables_dir + ": no coefficient tables to export (make them with `servodrift run', or "
                                    "export the reduced-order tables with `servodrift export-fmu --reduced-order')");
    const system::StageTables tables = system::StageTables::read(tables_dir, valve);
    const system::StageFunctions f(tables);
    ExportedFmu e;
    std::tie(e.lowest_temperature, e.highest_temperature) = table_temperature_range(f);
    const Layout l = layout(valve, f);
    e.variables = l.variables.size();

    Entries entries = {{"binaries/linux64/servodrift_valve.so", read_file(fmu_library())},
                       {"resources/parameters.prm", valve.parameter_file}};
    std::vector<const Table *> used = {&tables.torque_motor, &tables.spring_tube, &tables.fixed_orifice,
                                       &tables.nozzle_flapper};
    for (const auto *bore : {&tables.fixed_orifice_bore, &tables.nozzle_flapper_bore})
      if (*bore)
        used.push_back(&**bore);
    std::ostringstream levels;
    for (const Table *t : used)
      {
        entries.push_back({"resources/tables/" + t->name() + ".csv", read_file(tables_dir + "/" + t->name() + ".csv")});
        levels << "table " << t->name() << ".csv " << t->producer << "\n";
      }
    const std::string guid = guid_of(entries);

    std::ostringstream provenance;
    provenance << "guid " << guid << "\n"
               << "parameters-sha256 " << valve.parameters_sha256 << "\n"
               << "producer " << producer_string("export-fmu") << "\n"
               << "valve " << valve.source << "\n"
               << "model-levels torque_motor=" << to_string(valve.torque_motor.model_level)
               << " spring_tube=" << to_string(valve.spring_tube.model_level)
               << " pilot_stage=" << to_string(valve.pilot.model_level) << "\n"
               << "mesh-resolutions torque_motor=" << format_cell(valve.torque_motor.field_mesh_resolution)
               << " spring_tube=" << format_cell(valve.spring_tube.field_mesh_resolution)
               << " pilot_stage=" << format_cell(valve.pilot.field_mesh.resolution) << "\n"
               << "temperature-range " << format_cell(e.lowest_temperature) << " " << format_cell(e.highest_temperature)
               << " degC\n"
               << levels.str();
    entries.push_back({"resources/provenance.txt", provenance.str()});

    ModelDescriptionInfo info;
    info.guid = guid;
    info.description = "double-nozzle-flapper pressure servo valve of " + valve.source + ", tables from " +
                       to_string(valve.pilot.model_level) + " pilot stage, " + format_cell(e.lowest_temperature) + " to " +
                       format_cell(e.highest_temperature) + " degC";
    info.generation_tool = producer_string("");
    info.version = version();
    info.generated_at = utc_now();
    info.tolerance = valve.dynamics.relative_tolerance;
    entries.insert(entries.begin(), {"modelDescription.xml", model_description(l, info)});
    entries.push_back({"documentation/index.html", documentation(l, provenance.str())});

    e.path = valve.output.directory + "/servodrift_valve.fmu";
    write_zip(e.path, entries);
    return e;
  }
} // namespace servodrift::fmu
