#include "flow/pilot_stage.h"

#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/pilot_closed_forms.h"
#include "flow/pilot_field_stage.h"

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
  } // namespace

  PilotTables compute_pilot_tables(const ValveDescription &valve)
  {
    if (valve.pilot.model_level == "field")
      return compute_pilot_field_tables(valve);
    return {compute_fixed_orifice_table(valve), compute_nozzle_flapper_table(valve)};
  }

  void run(const ValveDescription &valve)
  {
    const std::string producer = "flow/" + valve.pilot.model_level;
    PilotTables tables = compute_pilot_tables(valve);
    write_table(valve, tables.fixed_orifice, producer);
    write_table(valve, tables.nozzle_flapper, producer);
    // the model-form alternatives: the same sweep with another flow model, tables beside the
    // default's (the system stage reports their spread)
    for (const std::string &model : valve.pilot.model_form_alternatives)
      {
        ValveDescription alternative = valve;
        using FlowModel = PilotStageParameters::FlowModel;
        const FlowModel m = model == "laminar"                  ? FlowModel::automatic :
                            model == "k-epsilon"                ? FlowModel::k_epsilon :
                            model == "k-epsilon-launder-sharma" ? FlowModel::k_epsilon_launder_sharma :
                                                                  FlowModel::k_omega_sst;
        alternative.pilot.fixed_orifice_flow_model = alternative.pilot.nozzle_flow_model = m;
        alternative.output.flow_fields = OutputParameters::FlowFields::none;
        PilotTables other = compute_pilot_field_tables(alternative, "." + model);
        write_table(valve, other.fixed_orifice, producer + " (" + model + ")", model);
        write_table(valve, other.nozzle_flapper, producer + " (" + model + ")", model);
      }
  }
} // namespace servodrift::flow
