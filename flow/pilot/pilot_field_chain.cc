// The continuation chain of the field-level pilot stage and the helpers of its cases.
#include "flow/pilot/pilot_field_cases.h"
#include "flow/pilot/pilot_field_time_average.h"

#include "common/error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <stdexcept>

namespace servodrift::flow
{
  using namespace case_record;
  using FlowModel = PilotFieldSolutionParameters::FlowModel;

  namespace
  {
    /// The flow model of a case (D11): fixed, or laminar below the transition Reynolds number.
    Turbulence model_of_case(FlowModel m, double ideal_reynolds, double transition)
    {
      switch (m)
        {
          case FlowModel::laminar: return Turbulence::laminar;
          case FlowModel::k_epsilon: return Turbulence::k_epsilon;
          case FlowModel::k_epsilon_launder_sharma: return Turbulence::k_epsilon_launder_sharma;
          case FlowModel::k_omega_sst: return Turbulence::k_omega_sst;
          case FlowModel::automatic: break;
        }
      return ideal_reynolds < transition ? Turbulence::laminar : Turbulence::k_epsilon;
    }

    /// A solve's results into the case record.
    void record_result(std::vector<double> &record, const PilotFieldResult &r)
    {
      record[flow_rate] = r.flow_rate;
      record[discharge_coefficient] = r.discharge_coefficient;
      record[reynolds_number] = r.reynolds_number;
      record[flapper_force] = r.flapper_force;
      record[land_force] = r.land_force;
      record[jet_force] = r.jet_force;
      record[bore_pressure] = r.bore_pressure;
      record[minimum_absolute_pressure] = r.minimum_absolute_pressure;
      record[cavitating] = r.cavitating ? 1 : 0;
      record[max_wall_y_plus] = r.max_wall_y_plus;
      record[max_turbulent_viscosity_ratio] = r.max_turbulent_viscosity_ratio;
      record[iterations] = r.iterations;
    }

    /// The steady state a row stands on: its pressure level [Pa], its largest scaled residual and
    /// that equation's index (its flow model is the case's unless set otherwise).
    void record_state(std::vector<double> &record, double level, const Residuals &r)
    {
      record[state_level] = level;
      record[state_residual] = largest_residual(r);
      record[state_residual_equation] = largest_residual_index(r);
    }

    /// The table temperature whose cases go to VTU with `Output/Flow fields = reference'.
    double reference_table_temperature(const ValveDescription &valve)
    {
      double best = valve.sweeps.table_temperatures.front();
      for (double T : valve.sweeps.table_temperatures)
        if (std::abs(T - valve.operating.reference_temperature) < std::abs(best - valve.operating.reference_temperature))
          best = T;
      return best;
    }
  } // namespace

  bool beyond_verified(double field_discharge, double reduced_discharge)
  {
    return field_discharge > 0 && reduced_discharge > 0 &&
           std::abs(std::log(field_discharge / reduced_discharge)) > std::log(verified_discharge_factor);
  }

  double computed_case_flag(double field_discharge, double reduced_discharge, double reynolds_number)
  {
    if (!beyond_verified(field_discharge, reduced_discharge))
      return flags::computed;
    return reynolds_number < creeping_reynolds_number ? flags::field_reference : flags::beyond_verified;
  }

  double span(const ValveDescription &valve)
  {
    return valve.operating.supply_pressure - valve.operating.return_pressure;
  }

  std::vector<double> scaled(const std::vector<double> &fractions, double scale)
  {
    std::vector<double> v;
    for (double f : fractions)
      v.push_back(f * scale);
    return v;
  }

  const char *model_name(Turbulence t)
  {
    switch (t)
      {
        case Turbulence::laminar: return "laminar";
        case Turbulence::k_epsilon: return "k-epsilon";
        case Turbulence::k_epsilon_launder_sharma: return "k-epsilon-launder-sharma";
        case Turbulence::k_omega_sst: return "k-omega-sst";
      }
    return "?";
  }

  std::string flow_directory(const ValveDescription &valve) { return valve.output.directory + "/flow"; }

  std::string vtu_name(PilotGeometry g, double T, double h, double dp)
  {
    char name[96];
    if (g == PilotGeometry::fixed_orifice)
      std::snprintf(name, sizeof name, "fixed_orifice_T%.1f_dp%.3fMPa.vtu", T, dp * 1e-6);
    else
      std::snprintf(name, sizeof name, "nozzle_flapper_T%.1f_h%.2fum_dp%.3fMPa.vtu", T, h * 1e6, dp * 1e-6);
    return name;
  }

  bool writes_fields(const ValveDescription &valve, double T)
  {
    switch (valve.output.flow_fields)
      {
        case OutputParameters::FlowFields::all: return true;
        case OutputParameters::FlowFields::none: return false;
        case OutputParameters::FlowFields::reference: return T == reference_table_temperature(valve);
      }
    return false;
  }

  std::vector<double> Chain::solve(double h, double dp, const std::optional<FlowFields> &start)
  {
    const auto begin = std::chrono::steady_clock::now();
    const auto &pilot = valve.pilot;
    const bool orifice = kind == PilotGeometry::fixed_orifice;
    if (!orifice && h != current_gap)
      cases.clear(), current_gap = h; // another mesh
    // the model: by the ideal-velocity Reynolds number of this case
    const double nu = conditions.fluid.viscosity / conditions.fluid.density;
    const auto g = closed_forms.geometry();
    const double length = orifice ? g.fixed_orifice_diameter : 2 * h;
    const double ideal_Re = length * std::sqrt(2 * dp / conditions.fluid.density) / nu;
    const Turbulence t = orifice ? model_of_case(pilot.field_solution.fixed_orifice_flow_model, ideal_Re, pilot.field_solution.fixed_orifice_transition_reynolds) :
                                   model_of_case(pilot.field_solution.nozzle_flow_model, ideal_Re, pilot.field_solution.nozzle_transition_reynolds);
    auto &slot = cases[t];
    if (!slot)
      {
        PilotFieldCase c = conditions;
        c.turbulence = t;
        slot = std::make_unique<PilotField>(settings, kind, c, h);
      }
    if (start)
      slot->set_fields(*start);
    else if (last && last_model != t) // the chain switched model: from a state of the new one if offered
      {
        const auto other = offered.find(t);
        slot->set_fields(other != offered.end() ? other->second : *last);
        if (other != offered.end())
          offered.erase(other); // once: later switches have this chain's own state of the model
      }
    const std::string vtu = flow_directory(valve) + "/" + vtu_name(kind, conditions.temperature, h, dp);
    failure_output = writes_fields(valve, conditions.temperature) ? vtu : "";
    slot->set_failure_output(failure_output);

    std::vector<double> record(record_length, 0.0);
    record[temperature] = conditions.temperature;
    record[gap] = h;
    record[pressure_difference] = dp;
    record[model] = record[state_model] = double(t);
    record[state_level] = record[state_residual_equation] = -1;
    const OrificeState reduced = orifice ? closed_forms.fixed_orifice(dp) : closed_forms.nozzle(h, dp);
    record[reduced_discharge_coefficient] = reduced.discharge_coefficient;
    record[reduced_flapper_force] = reduced.flapper_force;
    const std::string where = std::string(orifice ? "fixed orifice" : "nozzle-flapper") + " at " +
                              format_number(conditions.temperature) + " degC" +
                              (orifice ? "" : ", gap " + format_number(h * 1e6) + " um") + ", dp " +
                              format_number(dp * 1e-6) + " MPa (" + model_name(t) + ")";
    const CaseOutcome outcome = solve_with_retry(slot, t, h, dp, start.has_value());
    if (outcome.kind == CaseOutcome::Kind::converged)
      {
        record_result(record, outcome.result);
        record_state(record, dp, outcome.result.residuals);
        record[flag] =
          computed_case_flag(record[discharge_coefficient], reduced.discharge_coefficient, record[reynolds_number]);
        last = slot->fields();
        last_model = t;
        last_dp = dp;
        if (writes_fields(valve, conditions.temperature))
          slot->write_vtu(vtu);
      }
    else // flagged, the reduced order stands in
      {
        // a case that stalls may have no steady solution: its time average stands for it
        if (valve.pilot.time_average.enabled && outcome.kind == CaseOutcome::Kind::stalled &&
            time_average_of(*slot, dp, where, outcome.message, record))
          {
            record[flag] = flags::time_averaged;
            record[wall_time] = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            if (last) // the chain goes on from its last steady state
              slot->set_fields(*last);
            return record;
          }
        std::cerr << "servodrift: warning: " << where << ": " << outcome.message
                  << "; its table row is flagged 2 and carries the reduced-order value\n";
        record[flow_rate] = reduced.flow_rate;
        record[discharge_coefficient] = reduced.discharge_coefficient;
        record[reynolds_number] = reduced.reynolds_number;
        record[flapper_force] = reduced.flapper_force;
        record[flag] = flags::not_converged;
        if (outcome.kind == CaseOutcome::Kind::stalled && outcome.residuals_known)
          record_state(record, outcome.level, outcome.residuals);
        else if (outcome.kind == CaseOutcome::Kind::stalled)
          record[state_level] = outcome.level;
        if (outcome.k_epsilon_state)
          record[state_model] = double(Turbulence::k_epsilon);
        // the next case continues from the last converged fields, or starts up again
        if (last)
          slot->set_fields(*last);
        else
          slot.reset();
      }
    record[wall_time] = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return record;
  }

  bool Chain::time_average_of(PilotField &field, double dp, const std::string &where, const std::string &why,
                              std::vector<double> &record)
  {
    std::cerr << "servodrift: note: " << where << ": " << why << "; marching it in time for its time average\n";
    TimeAverage a;
    try
      {
        // `Report interval': every this many steps; otherwise a line at every tenth of the run
        // (a time average takes minutes), unless `Output/Progress' is none
        // (of the steps planned so far: a mean still uncertain gets more)
        const unsigned int interval = valve.flow_solver.report_interval;
        const unsigned int tenth = std::max(1u, valve.pilot.time_average.steps / 10);
        const bool tenths = interval == 0 && valve.output.progress != OutputParameters::Progress::none;
        a = time_average(field, dp, valve.pilot.time_average, [&](unsigned int step, unsigned int planned, double time, const PilotFieldResult &r) {
          if (interval > 0 && step % interval == 0)
            std::fprintf(stderr, "  time step %u of %u, t %.4g s: C_d %.6f, flapper force %.6f N, %u iterations%s%s, largest "
                         "residual %s %.3g\n", step, planned, time, r.discharge_coefficient, r.flapper_force, r.iterations,
                         r.step_converged ? "" : " (capped)", r.cavitating ? ", cavitating" : "",
                         residual_names[largest_residual_index(r.residuals)], largest_residual(r.residuals));
          else if (tenths && step % tenth == 0)
            std::fprintf(stderr, "servodrift: %s: time step %u of %u (t %.3g s), C_d %.4f\n", where.c_str(), step, planned,
                         time, r.discharge_coefficient);
        }, [&](const TimeAverage &rejected) {
          std::fprintf(stderr,
                       "servodrift: note: %s: %u of its %u averaged time steps at Courant number %g stopped at the "
                       "step's iteration cap short of its tolerance (held by %s), more than %g %%: marched again at "
                       "Courant number %g (`Pilot stage/Time average/Step halvings')\n",
                       where.c_str(), rejected.unconverged_steps, rejected.averaged_steps, rejected.courant_number,
                       capped_steps_held_by(rejected).c_str(), 100 * unconverged_steps_limit, rejected.courant_number / 2);
        });
      }
    catch (const std::exception &e) // diverged, or no flow to set a time step by
      {
        std::cerr << "servodrift: warning: " << where << ": its time average failed too: " << e.what() << "\n";
        return false;
      }
    record[averaged_discharge_coefficient] = a.mean.discharge_coefficient;
    record[discharge_coefficient_spread] = a.discharge_coefficient_spread;
    record[discharge_coefficient_uncertainty] = a.discharge_coefficient_uncertainty;
    record[averaged_flapper_force] = a.mean.flapper_force;
    record[flapper_force_spread] = a.flapper_force_spread;
    record[flapper_force_uncertainty] = a.flapper_force_uncertainty;
    record[averaged_time] = a.averaged_time;
    record[time_step] = a.time_step;
    record[unconverged_steps] = a.unconverged_steps;
    record[decorrelation_steps] = a.decorrelation_steps;
    const TimeAverageVerdict verdict = time_average_verdict(a, valve.pilot.time_average.uncertainty_limit);
    if (!verdict.stands())
      {
        std::cerr << "servodrift: warning: " << where << ": " << verdict.reason
                  << ": listed in flow/*_time_averages.csv, not used\n";
        return false;
      }
    if (a.unconverged_steps > 0)
      std::cerr << "servodrift: note: " << where << ": " << a.unconverged_steps << " of its " << a.averaged_steps
                << " averaged time steps stopped at the step's iteration cap (`Pilot stage/Time average/Step "
                   "iterations') short of its tolerance (held by "
                << capped_steps_held_by(a) << ")\n";
    record_result(record, a.mean);
    if (!failure_output.empty()) // the case's VTU (`Output/Flow fields'): the mean flow
      {
        field.set_fields(a.mean_fields);
        field.write_vtu(failure_output);
      }
    return true;
  }

  void Chain::resume(const State &s)
  {
    last = s.fields, last_model = s.model, last_dp = s.pressure_difference;
    PilotFieldCase c = conditions;
    c.turbulence = s.model;
    auto &slot = cases[s.model];
    slot = std::make_unique<PilotField>(settings, kind, c, current_gap > 0 ? current_gap : 0);
    slot->set_fields(s.fields);
  }
} // namespace servodrift::flow
