// The outputs of the field-level pilot stage's cases: flow/<geometry>_cases.csv with its .pvd
// collection, the counts on stderr, and the fixed_orifice and nozzle_flapper tables.
#include "flow/pilot/pilot_field_cases.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/version.h"
#include "common/vtu_output.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>
#include <utility>

namespace servodrift::embedded
{
  extern const char *const nozzle_mesh_errors_csv; ///< doc/benchmarks/nozzle_mesh_errors.csv
} // namespace servodrift::embedded

namespace servodrift::flow
{
  using namespace case_record;

  namespace
  {
    std::size_t count_flagged(const CaseRows &records, std::size_t column, double value)
    {
      std::size_t n = 0;
      for (const auto &r : records)
        n += r[column] == value;
      return n;
    }

    /// The errors of resolution `resolution' in doc/benchmarks/nozzle_mesh_errors.csv (written by
    /// bench/bench_mesh_convergence, compiled in): the smallest and largest of C_dn's and of the
    /// flapper force's, the gaps [m], the cavitation settings and how many rows rest on two levels.
    struct MeasuredErrors
    {
      double lowest_discharge = 0, highest_discharge = 0, lowest_force = 0, highest_force = 0;
      std::vector<double> gaps;
      std::set<std::string> cavitation; ///< "on", "off"
      std::size_t rows = 0, two_level_rows = 0;
    };

    MeasuredErrors measured_mesh_errors(double resolution)
    {
      MeasuredErrors e;
      const CsvDocument errors = CsvDocument::parse(embedded::nozzle_mesh_errors_csv);
      const std::size_t at_resolution = errors.column("resolution[1]"), at_gap = errors.column("gap[m]"),
                        at_discharge = errors.column("discharge_coefficient_error[1]"),
                        at_force = errors.column("flapper_force_error[1]"), at_estimate = errors.column("estimate"),
                        at_cavitation = errors.column("cavitation");
      for (const auto &row : errors.rows)
        {
          if (std::stod(row.at(at_resolution)) != resolution)
            continue;
          const double discharge = std::stod(row.at(at_discharge)), force = std::stod(row.at(at_force));
          const double gap = std::stod(row.at(at_gap));
          if (e.rows++ == 0)
            e.lowest_discharge = e.highest_discharge = discharge, e.lowest_force = e.highest_force = force;
          e.lowest_discharge = std::min(e.lowest_discharge, discharge);
          e.highest_discharge = std::max(e.highest_discharge, discharge);
          e.lowest_force = std::min(e.lowest_force, force);
          e.highest_force = std::max(e.highest_force, force);
          e.two_level_rows += row.at(at_estimate).rfind("two levels", 0) == 0;
          e.cavitation.insert(row.at(at_cavitation));
          if (std::find(e.gaps.begin(), e.gaps.end(), gap) == e.gaps.end())
            e.gaps.push_back(gap);
        }
      return e;
    }

    std::string percent(double fraction)
    {
      char s[32];
      std::snprintf(s, sizeof s, "%+.1f %%", 100 * fraction);
      return s;
    }

    /// A document of the field-level cases: its header lines and the columns of a case's inputs.
    CsvDocument case_document(const ValveDescription &valve, const std::string &output, const std::string &description)
    {
      CsvDocument doc;
      doc.comments = {"servodrift-output " + output, description, "producer " + producer_string("flow/field"),
                      "parameters-sha256 " + valve.parameters_sha256};
      doc.columns = {"temperature[degC]", "gap[m]", "pressure_difference[Pa]"};
      return doc;
    }

    /// flow/<geometry>_time_averages<variant>.csv: the cases without a steady solution, their time
    /// averages and spreads (flow/pilot/pilot_field_time_average.h).
    void write_time_averages(const ValveDescription &valve, const std::string &name, const CaseRows &records,
                             const std::string &variant)
    {
      CsvDocument doc = case_document(
        valve, name + "_time_averages",
        "field-level cases whose steady iteration stalled, marched in time (BDF2; URANS if turbulent): the mean and the standard "
        "deviation (spread) over the averaged time, the standard error of the mean (uncertainty, batch means) and the "
        "averaged steps whose equations the step's iteration cap stopped short of its tolerance, the lag at which "
        "the autocorrelation of C_d or the force first falls to zero (the averaged steps must hold 5 of it) "
        "(Pilot stage/Time average: Steps, Averaged fraction, Courant number, Step iterations); flag 5: the table "
        "uses the mean, 2: its uncertainty is beyond Pilot stage/Time average/Uncertainty limit, more than a tenth of its "
        "steps were capped or its window does not span 5 lags, and the reduced-order value stands in");
      doc.columns.insert(doc.columns.end(), {"discharge_coefficient[1]",
                     "discharge_coefficient_spread[1]",
                     "discharge_coefficient_uncertainty[1]",
                     "flapper_force[N]",
                     "flapper_force_spread[N]",
                     "flapper_force_uncertainty[N]",
                     "time_step[s]",
                     "averaged_time[s]",
                     "unconverged_steps[1]",
                     "decorrelation_steps[1]",
                     "flag[1]"});
      for (const auto &r : records)
        if (r[averaged_time] > 0)
          doc.rows.push_back({format_cell(r[temperature]), format_cell(r[gap]), format_cell(r[pressure_difference]),
                              format_cell(r[averaged_discharge_coefficient]), format_cell(r[discharge_coefficient_spread]),
                              format_cell(r[discharge_coefficient_uncertainty]), format_cell(r[averaged_flapper_force]),
                              format_cell(r[flapper_force_spread]), format_cell(r[flapper_force_uncertainty]),
                              format_cell(r[time_step]), format_cell(r[averaged_time]),
                              format_cell(r[unconverged_steps]), format_cell(r[decorrelation_steps]),
                              format_cell(r[flag])});
      write_file_atomically(flow_directory(valve) + "/" + name + "_time_averages" + variant + ".csv", doc.text());
    }

    /// A note for each case flagged 2 (the table's rows do not say which model, state or fields):
    /// where it is, its nearest steady state's largest scaled residual and the VTU of that state.
    void add_unconverged_case_notes(Table &table, const ValveDescription &valve, PilotGeometry g,
                                    const CaseRows &records)
    {
      const bool orifice = g == PilotGeometry::fixed_orifice;
      for (const auto &r : records)
        {
          if (r[flag] != flags::not_converged)
            continue;
          std::string note = "flag 2 at " + format_number(r[temperature]) + " degC" +
                             (orifice ? "" : ", gap " + format_number(r[gap] * 1e6) + " um") + ", dp " +
                             format_number(r[pressure_difference] * 1e-6) + " MPa (" +
                             model_name(Turbulence(int(r[model]))) + "): ";
          if (r[state_level] < 0)
            {
              table.notes.push_back(note + "no attempt converged or left a state (each diverged)");
              continue;
            }
          note += "no attempt converged; the nearest state";
          if (r[state_model] != r[model])
            note += std::string(" (") + model_name(Turbulence(int(r[state_model]))) +
                    "'s stall, from which the case's model was to start)";
          if (r[state_level] == 0)
            note += ", in the start-up from rest,";
          else if (r[state_level] != r[pressure_difference])
            note += ", at " + format_number(r[state_level] * 1e-6) + " MPa on the way to the case's level,";
          if (r[state_residual_equation] >= 0)
            note += " has a largest scaled residual of " + format_number(r[state_residual]) + " (" +
                    residual_names[int(r[state_residual_equation])] + ")";
          else
            note += " is the start an attempt diverged from, its residuals not known";
          if (writes_fields(valve, r[temperature]))
            note += "; its fields in flow/" + vtu_name(g, r[temperature], r[gap], r[pressure_difference]);
          table.notes.push_back(note);
        }
    }
  } // namespace

  std::string nozzle_mesh_error_note(const ValveDescription &valve)
  {
    const double resolution = valve.pilot.field_mesh.resolution;
    const std::string source = "(bench/bench_mesh_convergence, doc/benchmarks/nozzle_mesh_errors.csv)";
    if (valve.pilot.field_solution.nozzle_flow_model != PilotFieldSolutionParameters::FlowModel::k_epsilon)
      return "mesh resolution " + format_number(resolution) +
             ": the nozzle's discretisation error was measured with the default two-layer k-epsilon " + source +
             "; for this flow model see doc/validation.md";
    const MeasuredErrors e = measured_mesh_errors(resolution);
    if (e.rows == 0)
      return "mesh resolution " + format_number(resolution) +
             ": the nozzle's discretisation error is not measured at this resolution " + source;
    std::string gaps;
    for (double gap : e.gaps)
      gaps += (gaps.empty() ? "" : ", ") + format_number(gap * 1e6);
    return "mesh resolution " + format_number(resolution) +
           ": discretisation error measured on RV-1 at 40 degC with the default two-layer k-epsilon " + source +
           ": C_dn " + percent(e.lowest_discharge) + " to " + percent(e.highest_discharge) + ", flapper force " +
           percent(e.lowest_force) + " to " + percent(e.highest_force) + " at gaps " + gaps +
           " um, " + (e.cavitation.size() == 2 ? "with and without cavitation" : "cavitation " + *e.cavitation.begin()) +
           (e.two_level_rows > 0 ? " (" + std::to_string(e.two_level_rows) + " of " + std::to_string(e.rows) +
                                     " from two levels)" :
                                   "");
  }

  void write_case_summary(const ValveDescription &valve, PilotGeometry g, const CaseRows &records,
                          const std::string &variant)
  {
    const bool orifice = g == PilotGeometry::fixed_orifice;
    const std::string name = orifice ? "fixed_orifice" : "nozzle_flapper";
    on_rank_zero([&] {
      CsvDocument doc = case_document(
        valve, name + "_cases",
        "field-level " + std::string(orifice ? "fixed-orifice" : "nozzle-flapper") +
          " cases: results, diagnostics (model.md 4.2, C12) and the reduced-order values (E21-E23) beside them; flag "
          "2 = not converged (the table carries the reduced-order value), 4 = beyond the verified range (C_d and the "
          "reduced-order C_d differ by more than a factor " +
          format_number(verified_discharge_factor) + "), 5 = no steady solution: the time average (" + name +
          "_time_averages.csv), 6 = they differ so in creeping flow (Re < " + format_number(creeping_reynolds_number) +
          "), where the field level is the reference; the steady state a row stands on, the converged solution or a flag 2 "
          "case's nearest state (the one in its VTU; empty: no attempt left one): its pressure difference (the case's, or "
          "a level on the way to it), its largest scaled residual and that equation (empty: not known, as for the start "
          "an attempt diverged from); a pressure difference of 0: a state of the start-up from rest");
      doc.columns.insert(doc.columns.end(), {"flow_model[-]",
                     "flow_rate[m^3/s]",
                     "discharge_coefficient[1]",
                     "reduced_order_discharge_coefficient[1]",
                     "reynolds_number[1]",
                     "flapper_force[N]",
                     "reduced_order_flapper_force[N]",
                     "land_force[N]",
                     "jet_force[N]",
                     "bore_pressure[Pa]",
                     "minimum_absolute_pressure[Pa]",
                     "below_vapour_pressure[1]",
                     "max_wall_y_plus[1]",
                     "max_turbulent_viscosity_ratio[1]",
                     "iterations[1]",
                     "state_pressure_difference[Pa]",
                     "largest_residual[1]",
                     "largest_residual_equation[-]",
                     "wall_time[s]",
                     "flag[1]"});
      std::vector<std::pair<double, std::string>> datasets;
      for (const auto &r : records)
        {
          const bool converged =
            r[flag] == flags::computed || r[flag] == flags::beyond_verified || r[flag] == flags::time_averaged ||
            r[flag] == flags::field_reference;
          const bool known = r[state_residual_equation] >= 0;
          auto cell = [&](double v, bool defined = true) { return defined ? format_cell(v) : std::string(); };
          doc.rows.push_back({cell(r[temperature]), cell(r[gap], !orifice), cell(r[pressure_difference]),
                              model_name(Turbulence(int(r[model]))), cell(r[flow_rate]), cell(r[discharge_coefficient]),
                              cell(r[reduced_discharge_coefficient]), cell(r[reynolds_number]),
                              cell(r[flapper_force], !orifice), cell(r[reduced_flapper_force], !orifice),
                              cell(r[land_force], !orifice && converged), cell(r[jet_force], !orifice && converged),
                              cell(r[bore_pressure], !orifice && converged), cell(r[minimum_absolute_pressure], converged),
                              cell(r[cavitating], converged), cell(r[max_wall_y_plus], converged),
                              cell(r[max_turbulent_viscosity_ratio], converged),
                              cell(r[iterations], converged), cell(r[state_level], r[state_level] >= 0),
                              cell(r[state_residual], known), known ? residual_names[int(r[state_residual_equation])] : "",
                              cell(r[wall_time]), cell(r[flag])});
          if (converged && writes_fields(valve, r[temperature]))
            datasets.emplace_back(datasets.size(), vtu_name(g, r[temperature], r[gap], r[pressure_difference]));
        }
      write_file_atomically(flow_directory(valve) + "/" + name + "_cases" + variant + ".csv", doc.text());
      if (std::any_of(records.begin(), records.end(), [](const auto &r) { return r[averaged_time] > 0; }))
        write_time_averages(valve, name, records, variant);
      if (!datasets.empty())
        write_pvd_atomically(flow_directory(valve) + "/" + name + ".pvd", datasets);
    });
  }

  void report_counts(const char *what, const CaseRows &records, bool valve_cavitation)
  {
    if (mpi_rank() != 0)
      return;
    const std::size_t failed = count_flagged(records, flag, flags::not_converged);
    const std::size_t cavitating_cases = count_flagged(records, cavitating, 1);
    if (failed > 0)
      std::cerr << "servodrift: warning: " << failed << " of " << records.size() << " " << what
                << " cases did not converge (flag 2; see flow/*_cases.csv)\n";
    if (const std::size_t averaged = count_flagged(records, flag, flags::time_averaged); averaged > 0)
      std::cerr << "servodrift: note: " << averaged << " of " << records.size() << " " << what
                << " cases have no steady solution: their rows carry the time average (flag 5; the spread in "
                   "flow/*_time_averages.csv)\n";
    if (const std::size_t beyond = count_flagged(records, flag, flags::beyond_verified); beyond > 0)
      std::cerr << "servodrift: warning: " << beyond << " of " << records.size() << " " << what
                << " cases lie beyond the range where the field level was verified: their C_d differs from the "
                   "reduced-order value by more than a factor "
                << verified_discharge_factor << " (flag 4; see flow/*_cases.csv)\n";
    if (const std::size_t reference = count_flagged(records, flag, flags::field_reference); reference > 0)
      std::cerr << "servodrift: note: " << reference << " of " << records.size() << " " << what
                << " cases are creeping flows where the reduced-order closed forms leave their range: the field "
                   "level is the reference there (flag 6; see flow/*_cases.csv)\n";
    if (cavitating_cases > 0)
      std::cerr << "servodrift: note: " << cavitating_cases << " of " << records.size() << " " << what
                << " cases cavitate ("
                << (valve_cavitation ? "the equilibrium cavitation model holds those cells at the vapour pressure"
                                     : "Pilot stage/Field solution/Cavitation is off: the single-phase result stretches the "
                                       "liquid below its vapour pressure and is not physical there")
                << "; model.md C12; flow/*_cases.csv)\n";
  }

  Table fixed_orifice_table(const ValveDescription &valve, const CaseRows &records)
  {
    Table table(schemas::fixed_orifice);
    table.notes.push_back("mesh resolution " + format_number(valve.pilot.field_mesh.resolution) +
                          ": the orifice's discretisation error is measured laminar only (Re_0 493: 0.11 % between "
                          "resolutions 1 and 1.4), not at k-epsilon's Reynolds numbers (doc/validation.md)");
    add_unconverged_case_notes(table, valve, PilotGeometry::fixed_orifice, records);
    std::size_t next = 0;
    for (double T : valve.sweeps.table_temperatures)
      {
        table.rows.push_back({T, 0.0, 0.0, 0.0, 0.0, flags::limit}); // no pressure difference, no flow
        for (std::size_t j = 0; j < valve.sweeps.field_orifice_pressure_fractions.size(); ++j, ++next)
          {
            const auto &r = records[next];
            table.rows.push_back({T, r[pressure_difference], r[flow_rate], r[discharge_coefficient], r[reynolds_number], r[flag]});
          }
      }
    return table;
  }

  Table nozzle_flapper_table(const ValveDescription &valve, const CaseRows &records)
  {
    Table table(schemas::nozzle_flapper);
    table.notes.push_back(nozzle_mesh_error_note(valve));
    add_unconverged_case_notes(table, valve, PilotGeometry::nozzle_flapper, records);
    const auto gaps = scaled(valve.sweeps.field_gap_fractions, valve.pilot.null_gap);
    const auto dps = scaled(valve.sweeps.field_nozzle_pressure_fractions, span(valve));
    std::size_t next = 0;
    for (double T : valve.sweeps.table_temperatures)
      {
        const PilotClosedForms closed_forms(valve, T);
        // the closed gap: no flow, the control pressure on the bore's area (E23 at h = 0)
        table.rows.push_back({T, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, flags::limit});
        for (double dp : dps)
          table.rows.push_back({T, 0.0, dp, 0.0, 0.0, 0.0, closed_forms.nozzle(0.0, dp).flapper_force, flags::limit});
        for (double h : gaps)
          {
            table.rows.push_back({T, h, 0.0, 0.0, 0.0, 0.0, 0.0, flags::limit}); // no pressure difference
            for (std::size_t j = 0; j < dps.size(); ++j, ++next)
              {
                const auto &r = records[next];
                table.rows.push_back({T, h, r[pressure_difference], r[flow_rate], r[discharge_coefficient],
                                      r[reynolds_number], r[flapper_force], r[flag]});
              }
          }
      }
    return table;
  }
} // namespace servodrift::flow
