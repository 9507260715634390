// servodrift: the command line. Subcommands only, no physics: each calls one module's run().
#include "common/error.h"
#include "common/output_files.h"
#include "common/parameter_input.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/valve_description.h"
#include "common/version.h"
#include "flow/pilot/pilot_stage.h"
#include "fmu/export_fmu.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/system_stage.h"

#include <deal.II/base/mpi.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>

namespace
{
  using namespace servodrift;

  struct Options
  {
    std::string input;
    std::vector<std::string> overrides;
    std::string output;
    std::string format = "prm";
    bool calibrate = false, convergence = false;
    bool reduced_order = false;      ///< export-fmu: the reduced-order tables, made first
    std::string measured;            ///< calibrate: the measured data
    std::vector<std::string> free;   ///< calibrate: "Subsection/Key[=lower:upper]"
  };

  /// --set takes one value per occurrence, so that the valve file may follow the options
  void add_set_option(CLI::App *command, Options &o)
  {
    command->add_option("--set", o.overrides, "override one entry, \"Subsection/Key=value\" (repeatable)")
      ->expected(1)
      ->allow_extra_args(false)
      ->take_all();
  }

  void add_common_options(CLI::App *command, Options &o)
  {
    command->add_option("input", o.input, "valve description (.prm or .json); default: the built-in RV-1");
    add_set_option(command, o);
    command->add_option("-o,--output", o.output, "output directory (overrides Output/Directory)");
  }

  ValveDescription load(const Options &o)
  {
    std::vector<std::string> overrides = o.overrides;
    if (!o.output.empty())
      overrides.push_back("Output/Directory=" + o.output);
    return load_valve_description(o.input, overrides);
  }

  void say(const std::string &line)
  {
    if (mpi_rank() == 0)
      std::cout << line << std::endl;
  }

  /// Runs one step with its wall time on stdout.
  template <typename Step>
  void timed(const std::string &name, Step &&step)
  {
    const auto start = std::chrono::steady_clock::now();
    step();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.2f s", s);
    say("  " + name + ": " + buffer);
  }

  /// Before a run with a field-level stage (minutes of work): the whole chain on the reduced-order
  /// models, in memory and over the same table ranges, so that a valve the system model cannot run
  /// on such tables (an operating point beyond a table, a bridge without a null) is refused before
  /// the first stage writes (issue 24). At the reduced order the run itself is as quick.
  void check_before_field_stages(const ValveDescription &valve)
  {
    if (valve.torque_motor.model_level != ModelLevel::field && valve.spring_tube.model_level != ModelLevel::field &&
        valve.pilot.model_level != ModelLevel::field)
      return;
    ValveDescription reduced = valve;
    reduced.torque_motor.model_level = reduced.spring_tube.model_level = reduced.pilot.model_level =
      ModelLevel::reduced_order;
    reduced.output.progress = OutputParameters::Progress::none;
    auto &sw = reduced.sweeps;
    if (valve.pilot.model_level == ModelLevel::field) // the field tables' ranges: their rows and the added zero rows
      {
        sw.gap_fractions = sw.field_gap_fractions;
        sw.pressure_fractions = sw.field_orifice_pressure_fractions;
        sw.pressure_fractions.insert(sw.pressure_fractions.end(), sw.field_nozzle_pressure_fractions.begin(),
                                     sw.field_nozzle_pressure_fractions.end());
        for (auto *list : {&sw.gap_fractions, &sw.pressure_fractions})
          {
            list->push_back(0);
            std::sort(list->begin(), list->end());
            list->erase(std::unique(list->begin(), list->end()), list->end());
          }
      }
    try
      {
        system::StageTables tables;
        tables.torque_motor = magnetics::compute_torque_motor_table(reduced);
        tables.spring_tube = structure::compute_spring_tube_table(reduced);
        auto pilot = flow::compute_pilot_tables(reduced);
        tables.fixed_orifice = std::move(pilot.fixed_orifice);
        tables.nozzle_flapper = std::move(pilot.nozzle_flapper);
        system::check_operating_points(reduced, tables);
      }
    catch (const std::exception &e)
      {
        throw InputError(std::string(e.what()) + " (found by the reduced-order models before the field stages ran)");
      }
  }

  ValveDescription prepare(const Options &o, bool dynamics, bool tolerances, bool whole_run)
  {
    say(producer_string("on " + std::to_string(mpi_size()) + (mpi_size() == 1 ? " rank" : " ranks")));
    ValveDescription valve = load(o);
    if (dynamics) // `servodrift dynamics' runs them whatever `Dynamics/Enabled' says
      validate_dynamics(valve);
    if (tolerances) // as `servodrift tolerances' does the study whatever `Tolerances/Enabled' says
      validate_tolerances(valve);
    if (whole_run)
      {
        validate_table_ranges(valve);
        check_before_field_stages(valve);
      }
    say("valve description: " + valve.source + ", output: " + valve.output.directory + "/");
    return valve;
  }

  /// Runs the stages of one subcommand as one OutputTransaction: if any fails, the output directory
  /// is left as it was before the run (every rank undoes its own files, then rank 0 removes the
  /// directories the run created).
  template <typename Stages>
  void transaction(const ValveDescription &valve, Stages &&stages)
  {
    OutputTransaction output(valve.output.directory);
    try
      {
        stages();
      }
    catch (...)
      {
        output.roll_back();
        mpi_barrier(); // errors are collective (run_sweep, on_rank_zero): every rank is here
        if (mpi_rank() == 0)
          output.remove_created_directories();
        throw;
      }
    mpi_barrier();
    output.commit();
  }

  int run_main(int argc, char **argv)
  {
    CLI::App app{"servodrift: thermal drift of the operating point of a double-nozzle-flapper pressure servo valve, "
                 "from first principles (torque motor, pilot stage, spring tube, whole valve)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", producer_string(""));
    Options o;

    auto *run = app.add_subcommand("run", "all stages -> tables -> fits -> drift maps -> report.md");
    auto *params = app.add_subcommand("params", "print the complete documented parameter file");
    auto *magnetics = app.add_subcommand("magnetics", "torque-motor stage alone: tables/torque_motor.csv");
    auto *structure = app.add_subcommand("structure", "spring-tube stage alone: tables/spring_tube.csv");
    auto *flow = app.add_subcommand("flow", "pilot-stage flow alone: tables/fixed_orifice.csv, tables/nozzle_flapper.csv");
    auto *system = app.add_subcommand("system", "system model alone, from the tables already in <output>/tables");
    auto *dynamics = app.add_subcommand(
      "dynamics", "system model with the dynamics (modes, step and frequency responses), from the tables in <output>/tables");
    auto *tolerances = app.add_subcommand(
      "tolerances", "system model with the tolerance study (Monte Carlo of the thermal null shift, yield, Sobol' "
                    "indices), from the tables in <output>/tables");
    auto *calibrate = app.add_subcommand(
      "calibrate", "fit free entries of the valve description to measured drift data, from the tables in <output>/tables");
    calibrate->add_option("measured", o.measured,
                          "measured data (CSV: temperature[degC], current[A], measured quantities with units)")
      ->required();
    calibrate->add_option("--free", o.free, "a free entry, \"Subsection/Key\" or \"Subsection/Key=lower:upper\" (repeatable)")
      ->expected(1)
      ->allow_extra_args(false)
      ->take_all();
    auto *export_fmu = app.add_subcommand(
      "export-fmu", "the valve of the tables in <output>/tables as an FMI 2.0 FMU (Model Exchange and "
                    "Co-Simulation): <output>/servodrift_valve.fmu");
    export_fmu->add_flag("--reduced-order", o.reduced_order,
                         "make the reduced-order tables first (seconds) instead of using those in <output>/tables");
    for (auto *c : {run, magnetics, structure, flow, system, dynamics, tolerances, calibrate, export_fmu})
      add_common_options(c, o);
    magnetics->add_flag("--calibrate", o.calibrate,
                        "C10: calibrate the field model's equivalent magnet width at T0 against the circuit");
    magnetics->add_flag("--convergence", o.convergence,
                        "field model: mesh convergence and outer-boundary study at T0 (magnetics/*.csv)");
    params->add_option("input", o.input, "valve description (.prm or .json); default: the built-in RV-1");
    add_set_option(params, o);
    params->add_option("--format", o.format, "prm (default), json or markdown")
      ->check(CLI::IsMember({"prm", "json", "markdown"}));

    try
      {
        app.parse(argc, argv);
      }
    catch (const CLI::ParseError &e)
      {
        if (e.get_exit_code() == 0) // --help, --version
          return mpi_rank() == 0 ? app.exit(e) : 0;
        if (mpi_rank() == 0)
          std::cerr << "servodrift: usage error: " << shown_input(e.what(), 300) << " (see `servodrift --help')"
                    << std::endl;
        return 2;
      }

    if (params->parsed())
      {
        const ParameterFormat format = o.format == "json"     ? ParameterFormat::json :
                                       o.format == "markdown" ? ParameterFormat::markdown :
                                                                ParameterFormat::prm;
        const std::string text = print_parameters(o.input, o.overrides, format);
        load_valve_description(o.input, o.overrides); // refuse what would not run
        if (mpi_rank() == 0)
          std::cout << text;
        return 0;
      }

    const ValveDescription valve = prepare(o, dynamics->parsed(), tolerances->parsed(), run->parsed());
    const auto system_label = [](system::Analyses a) {
      return std::string("system: fits, drift maps, ") + (a.dynamics ? "dynamics, " : "") +
             (a.tolerances ? "tolerances, " : "") + "plots, report";
    };
    if (calibrate->parsed())
      {
        // everything checked before anything is written: the free entries, the measured file, the
        // model at the starting values
        std::vector<std::string> overrides = o.overrides;
        overrides.push_back("Output/Directory=" + valve.output.directory);
        const system::CalibrationRequest request{o.measured, o.free, o.input, overrides};
        const system::StageTables tables = system::StageTables::read(tables_directory(valve), valve);
        const system::CalibrationSetup setup = system::prepare_calibration(request, tables);
        transaction(valve, [&] {
          system::CalibrationResults results;
          timed("calibration (" + std::to_string(setup.parameters.size()) + " free, " +
                  std::to_string(setup.data.points.size()) + " measured values)",
                [&] { results = system::calibrate(request, setup, tables); });
          std::vector<std::string> calibrated_overrides = results.calibrated_overrides;
          calibrated_overrides.push_back("Output/Directory=" + valve.output.directory);
          const ValveDescription calibrated = load_valve_description(o.input, calibrated_overrides);
          system::Analyses analyses;
          analyses.calibration = &results;
          timed("system: fits, drift maps, plots, report of the calibrated valve", [&] { system::run(calibrated, analyses); });
          write_parameters_file(calibrated);
          say("results: " + valve.output.directory + "/calibration/, " + valve.output.directory + "/report.md");
        });
        return 0;
      }
    const auto write_fmu = [&](const ValveDescription &v) {
      timed("FMU", [&] {
        on_rank_zero([&] {
          const fmu::ExportedFmu e = fmu::export_fmu(v);
          say("  " + e.path + ": FMI 2.0, " + std::to_string(e.variables) + " variables, " +
              format_cell(e.lowest_temperature) + " to " + format_cell(e.highest_temperature) + " degC");
        });
      });
    };
    if (export_fmu->parsed())
      {
        if (!o.reduced_order)
          {
            write_fmu(valve); // from the tables already there; the archive is the only file written
            return 0;
          }
        Options r = o;
        for (const char *stage : {"Torque motor", "Spring tube", "Pilot stage"})
          r.overrides.push_back(std::string(stage) + "/Model level=reduced-order");
        const ValveDescription reduced = load(r);
        transaction(reduced, [&] {
          write_parameters_file(reduced);
          timed("magnetics (reduced-order)", [&] { magnetics::run(reduced); });
          timed("structure (reduced-order)", [&] { structure::run(reduced); });
          timed("flow (reduced-order)", [&] { flow::run(reduced); });
          write_fmu(reduced);
        });
        return 0;
      }
    transaction(valve, [&] {
      if (system->parsed() || dynamics->parsed() || tolerances->parsed())
        {
          // parameters.prm says how the tables were made: rewritten only once they are read and accepted
          const system::Analyses analyses{dynamics->parsed(), tolerances->parsed()};
          timed(system_label(analyses), [&] { system::run(valve, analyses); });
          write_parameters_file(valve);
          say("results: " + valve.output.directory + "/report.md, " + valve.output.directory + "/system/");
          return;
        }
      write_parameters_file(valve); // creates the output directory, or stops every rank with the reason
      if (run->parsed())
        {
          timed("magnetics (" + to_string(valve.torque_motor.model_level) + ")", [&] { magnetics::run(valve); });
          timed("structure (" + to_string(valve.spring_tube.model_level) + ")", [&] { structure::run(valve); });
          timed("flow (" + to_string(valve.pilot.model_level) + ")", [&] { flow::run(valve); });
          const system::Analyses analyses{valve.dynamics.enabled, valve.tolerances.enabled};
          timed(system_label(analyses), [&] { system::run(valve, analyses); });
          if (valve.output.fmu)
            write_fmu(valve);
          say("results: " + valve.output.directory + "/report.md, " + valve.output.directory + "/tables/, " +
              valve.output.directory + "/system/");
        }
      else if (magnetics->parsed() && (o.calibrate || o.convergence))
        {
          if (o.calibrate)
            timed("magnetics: C10 calibration", [&] { magnetics::calibrate(valve); });
          if (o.convergence)
            timed("magnetics: convergence study", [&] { magnetics::convergence_study(valve); });
          say("results: " + valve.output.directory + "/magnetics/");
        }
      else
        {
          if (magnetics->parsed())
            timed("magnetics (" + to_string(valve.torque_motor.model_level) + ")", [&] { magnetics::run(valve); });
          if (structure->parsed())
            timed("structure (" + to_string(valve.spring_tube.model_level) + ")", [&] { structure::run(valve); });
          if (flow->parsed())
            timed("flow (" + to_string(valve.pilot.model_level) + ")", [&] { flow::run(valve); });
          write_fits(valve);
          say("results: " + tables_directory(valve) + "/");
        }
    });
    return 0;
  }

} // namespace

int main(int argc, char **argv)
{
  servodrift::one_thread_per_process();
  servodrift::prepare_mpi_singleton();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      return run_main(argc, argv);
    }
  catch (const std::exception &e)
    {
      if (servodrift::mpi_rank() == 0)
        std::cerr << "servodrift: error: " << shown_input(e.what(), 340) << std::endl; // one line, printable
      return 1;
    }
}
