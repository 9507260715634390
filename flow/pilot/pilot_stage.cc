#include "flow/pilot/pilot_stage.h"

#include "common/error.h"
#include "common/output_files.h"
#include "common/pilot_closed_forms.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_field_stage.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace servodrift::flow
{
  namespace
  {
    std::vector<double> pressure_differences(const ValveDescription &valve)
    {
      std::vector<double> dp;
      const double span = valve.operating.supply_pressure - valve.operating.return_pressure;
      for (double f : valve.sweeps.pressure_fractions)
        dp.push_back(f * span);
      return dp;
    }

    Table compute_fixed_orifice_table(const ValveDescription &valve)
    {
      const auto &T = valve.sweeps.table_temperatures;
      const auto dp = pressure_differences(valve);
      Table table(schemas::fixed_orifice);
      table.rows = run_sweep(
        "flow: fixed orifice", T.size(),
        [&](std::size_t k) {
          const PilotClosedForms pilot(valve, T[k]);
          CaseRows rows;
          for (double p : dp)
            {
              const auto s = pilot.fixed_orifice(p);
              rows.push_back({T[k], p, s.flow_rate, s.discharge_coefficient, s.reynolds_number,
                              s.clamped ? flags::clamped : flags::computed});
            }
          return rows;
        },
        valve.output.progress);
      return table;
    }

    Table compute_nozzle_flapper_table(const ValveDescription &valve)
    {
      const auto &T = valve.sweeps.table_temperatures;
      const auto dp = pressure_differences(valve);
      std::vector<double> gaps;
      for (double f : valve.sweeps.gap_fractions)
        gaps.push_back(f * valve.pilot.null_gap);
      Table table(schemas::nozzle_flapper);
      table.rows = run_sweep(
        "flow: nozzle-flapper", T.size() * gaps.size(),
        [&](std::size_t k) {
          const double temperature = T[k / gaps.size()], h = gaps[k % gaps.size()];
          const PilotClosedForms pilot(valve, temperature);
          CaseRows rows;
          for (double p : dp)
            {
              const auto s = pilot.nozzle(h, p);
              rows.push_back({temperature, h, p, s.flow_rate, s.discharge_coefficient, s.reynolds_number,
                              s.flapper_force, s.clamped ? flags::clamped : flags::computed});
            }
          return rows;
        },
        valve.output.progress);
      return table;
    }

    /// Whether the flow stage also tabulates the flows at wider bores (`Pilot stage/Bore
    /// sensitivity'): automatically where a side's bore will differ from the tables' and the
    /// closed forms' ratio does not hold, at the field level.
    bool bore_tables_wanted(const ValveDescription &valve)
    {
      using Choice = BoreSensitivityParameters::Tables;
      if (valve.pilot.bore_sensitivity.tables != Choice::automatic)
        return valve.pilot.bore_sensitivity.tables == Choice::on;
      if (valve.pilot.model_level != ModelLevel::field)
        return false;
      const auto &a = valve.asymmetry;
      if (a.left.orifice_diameter != 0 || a.right.orifice_diameter != 0 || a.left.nozzle_diameter != 0 ||
          a.right.nozzle_diameter != 0)
        return true;
      if (!valve.tolerances.enabled)
        return false;
      for (std::size_t k : valve.tolerances.active())
        if (valve.tolerances.distributions[k].name.find("diameter") != std::string::npos)
          return true;
      return false;
    }

    /// The entries of `axis' nearest each target, once each, in increasing order: a few points of a
    /// table's axis.
    std::vector<double> nearest(const std::vector<double> &axis, std::initializer_list<double> targets)
    {
      std::vector<double> picked;
      for (double t : targets)
        picked.push_back(*std::min_element(axis.begin(), axis.end(), [t](double a, double b) {
          return std::abs(a - t) < std::abs(b - t);
        }));
      std::sort(picked.begin(), picked.end());
      picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
      return picked;
    }

    /// The ratios of the pilot flows (and the nozzle's jet force) at bores one step wider to the
    /// tables', at a few points per temperature: where the null and the regulating valve work (the
    /// orifice at a quarter and three quarters of the span, the nozzle at 0.75 and 1.25 x0 and
    /// half and the whole span). Both bores widen in the one sweep (each table sees only its own).
    /// Where either case did not converge the closed forms' ratio stands in, flagged; the limits
    /// without flow (dp = 0, a closed gap, on every temperature alike) are left out.
    std::pair<Table, Table> bore_tables(const ValveDescription &valve, const PilotTables &nominal)
    {
      const double step = valve.pilot.bore_sensitivity.step;
      ValveDescription wider = valve;
      wider.pilot.fixed_orifice_diameter += step;
      wider.pilot.nozzle_diameter += step;
      wider.pilot.field_solution.model_form_alternatives.clear();
      wider.output.flow_fields = OutputParameters::FlowFields::none;
      SweepParameters &s = wider.sweeps;
      s.pressure_fractions = nearest(valve.sweeps.pressure_fractions, {0.25, 0.5, 0.75, 1});
      s.gap_fractions = nearest(valve.sweeps.gap_fractions, {0.75, 1, 1.25});
      // the field orifice on its whole path: its first case (the lowest pressure) sets the path,
      // and another path can land on another cavitating state (doc/method.md)
      s.field_gap_fractions = nearest(valve.sweeps.field_gap_fractions, {0.75, 1, 1.25});
      s.field_nozzle_pressure_fractions = nearest(valve.sweeps.field_nozzle_pressure_fractions, {0.5, 1});
      const PilotTables at = valve.pilot.model_level == ModelLevel::field ? compute_pilot_field_tables(wider, ".bore") :
                                                                  compute_pilot_tables(wider);
      const auto ratios = [&](const Table &nominal_table, const Table &wider_table, const TableSchema &schema) {
        const std::size_t axes = nominal_table.schema().n_axes, flag = nominal_table.rows.front().size() - 1;
        const std::size_t q = nominal_table.column_index("flow_rate");
        const bool nozzle = axes == 3;
        const std::size_t force = nozzle ? nominal_table.column_index("flapper_force") : 0;
        std::map<std::vector<double>, const std::vector<double> *> by_point;
        for (const auto &row : nominal_table.rows)
          by_point[{row.begin(), row.begin() + std::ptrdiff_t(axes)}] = &row;
        Table table(schema);
        for (const auto &row : wider_table.rows)
          {
            const std::vector<double> point(row.begin(), row.begin() + std::ptrdiff_t(axes));
            const std::vector<double> &base = *by_point.at(point);
            if (row[flag] == flags::limit || base[flag] == flags::limit) // no flow (dp = 0, a closed gap)
              continue;
            std::vector<double> out = point;
            out.push_back(step);
            const bool converged = row[flag] != flags::not_converged && base[flag] != flags::not_converged;
            if (converged)
              {
                out.push_back(row[q] / base[q]);
                if (nozzle)
                  out.push_back(row[force] / base[force]);
                out.push_back(std::max(row[flag], base[flag]));
              }
            else
              {
                const double T = point[0], dp = point.back();
                const PilotClosedForms narrow(valve, T), wide(wider, T);
                if (nozzle)
                  {
                    const OrificeState a = narrow.nozzle(point[1], dp), b = wide.nozzle(point[1], dp);
                    out.insert(out.end(), {b.flow_rate / a.flow_rate, b.flapper_force / a.flapper_force});
                  }
                else
                  out.push_back(wide.fixed_orifice(dp).flow_rate / narrow.fixed_orifice(dp).flow_rate);
                out.push_back(flags::not_converged);
              }
            for (double v : out)
              if (!std::isfinite(v))
                throw std::logic_error("flow: the bore table " + schema.name + " has a non-finite ratio at " +
                                       format_number(point[0]) + " degC, dp " + format_number(point.back()) +
                                       " Pa (flow " + format_number(row[q]) + " over " + format_number(base[q]) + ")");
            table.rows.push_back(out);
          }
        return table;
      };
      return {ratios(nominal.fixed_orifice, at.fixed_orifice, schemas::fixed_orifice_bore),
              ratios(nominal.nozzle_flapper, at.nozzle_flapper, schemas::nozzle_flapper_bore)};
    }
  } // namespace

  PilotTables compute_pilot_tables(const ValveDescription &valve)
  {
    if (valve.pilot.model_level == ModelLevel::field)
      return compute_pilot_field_tables(valve);
    return {compute_fixed_orifice_table(valve), compute_nozzle_flapper_table(valve)};
  }

  void run(const ValveDescription &valve)
  {
    const std::string producer = "flow/" + to_string(valve.pilot.model_level);
    PilotTables tables = compute_pilot_tables(valve);
    write_table(valve, tables.fixed_orifice, producer);
    write_table(valve, tables.nozzle_flapper, producer);
    // the flows at wider bores where a side's bore will differ (or none, and none left from before)
    if (bore_tables_wanted(valve))
      {
        auto [orifice, nozzle] = bore_tables(valve, tables);
        write_table(valve, orifice, producer);
        write_table(valve, nozzle, producer);
      }
    else
      on_rank_zero([&] {
        for (const char *name : {"fixed_orifice_bore", "nozzle_flapper_bore"})
          remove_output_file(table_path(valve, name));
      });
    // the model-form alternatives: the same sweep with another flow model, tables beside the
    // default's (the system stage reports their spread)
    for (const std::string &model : valve.pilot.field_solution.model_form_alternatives)
      {
        ValveDescription alternative = valve;
        using FlowModel = PilotFieldSolutionParameters::FlowModel;
        const FlowModel m = model == "laminar"                  ? FlowModel::automatic :
                            model == "k-epsilon"                ? FlowModel::k_epsilon :
                            model == "k-epsilon-launder-sharma" ? FlowModel::k_epsilon_launder_sharma :
                                                                  FlowModel::k_omega_sst;
        alternative.pilot.field_solution.fixed_orifice_flow_model = alternative.pilot.field_solution.nozzle_flow_model = m;
        alternative.output.flow_fields = OutputParameters::FlowFields::none;
        PilotTables other = compute_pilot_field_tables(alternative, "." + model);
        write_table(valve, other.fixed_orifice, producer + " (" + model + ")", model);
        write_table(valve, other.nozzle_flapper, producer + " (" + model + ")", model);
      }
  }
} // namespace servodrift::flow
