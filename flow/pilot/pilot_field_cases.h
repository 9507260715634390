#pragma once
// The field-level pilot stage's cases (flow/pilot/pilot_field_stage.cc runs them): the record of one
// computed case, the continuation chain that computes a temperature's cases of one geometry, and the
// outputs built from the records (flow/<geometry>_cases.csv, the tables, the counts on stderr).
#include "common/sweep.h"
#include "common/table.h"
#include "common/valve_description.h"
#include "common/pilot_closed_forms.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_retry.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace servodrift::flow
{
  using Turbulence = FlowSolverParameters::Turbulence;

  /// One computed case: the record every chain returns, from which the table and
  /// flow/<geometry>_cases.csv are built (CaseRows: one record per case).
  namespace case_record
  {
    enum Field : std::size_t
    {
      temperature,
      gap,
      pressure_difference,
      flow_rate,
      discharge_coefficient,
      reynolds_number,
      flapper_force,
      land_force,
      jet_force,
      bore_pressure,
      minimum_absolute_pressure,
      cavitating,
      max_wall_y_plus,
      max_turbulent_viscosity_ratio,
      iterations,
      model,
      flag,
      reduced_discharge_coefficient,
      reduced_flapper_force,
      wall_time,
      // a time average (flag 5, or flag 2 where the uncertainty of its mean is beyond the limit):
      // the means, standard deviations and standard errors of the means over the averaged time,
      // that time and the time step (0: none)
      averaged_discharge_coefficient,
      discharge_coefficient_spread,
      discharge_coefficient_uncertainty,
      averaged_flapper_force,
      flapper_force_spread,
      flapper_force_uncertainty,
      averaged_time,
      time_step,
      unconverged_steps, ///< of the averaged steps: those the step's iteration cap stopped (TimeAverage)
      decorrelation_steps, ///< the lag at which C_d's or the force's autocorrelation first falls to zero
      // the steady state the row stands on: the converged solution, or a flagged case's nearest
      // state (the one in its VTU; CaseOutcome): its pressure level (-1: no state; 0: a state of
      // the start-up from rest), its largest scaled residual (PilotFieldResult::residuals) and that
      // equation's index in residual_names (-1: not known, as for a start that diverged)
      state_level,
      state_residual,
      state_residual_equation,
      state_model, ///< the flow model of that state (Turbulence): the case's, or k-epsilon's stall
      record_length
    };
  } // namespace case_record

  /// The field level was verified on RV-1's sweep over 40-120 degC, where its discharge coefficients
  /// lie within a factor 1.31 of the reduced-order closed forms E21-E22 (the orifice cavitating at
  /// the full span 0.77 of E21, the nozzle at 10 um 1.29 of E22; doc/validation.md), and in creeping
  /// flow against the lubrication limit. Beyond this factor elsewhere (a geometry far from RV-1's,
  /// the oil between creeping and the sweep's Reynolds numbers) the case is flagged 4 and counted in
  /// the report (issue 24).
  constexpr double verified_discharge_factor = 1.35;

  /// The case's C_d lies beyond verified_discharge_factor of the reduced-order one.
  bool beyond_verified(double field_discharge, double reduced_discharge);

  /// Below this Reynolds number (E17, E18) a case's flow is creeping: the field level tends to the
  /// creeping limits there (doc/validation.md, "The whole temperature range"), while E21 and E22,
  /// fitted to inertial flows and without the nozzle bore's viscous resistance, leave their range.
  /// Measured: the field's C_d over its creeping limit does not move with Re below it (the orifice
  /// 1.0120 at Re 0.2 and 4.3; RV-1's nozzle at 70 um 0.672 at Re 0.13 to 0.665 at Re 8.3).
  constexpr double creeping_reynolds_number = 10;

  /// A computed case's flag: computed within verified_discharge_factor of the closed forms E21/E22;
  /// beyond it, field_reference where the flow is creeping, beyond_verified elsewhere.
  double computed_case_flag(double field_discharge, double reduced_discharge, double reynolds_number);

  /// p_s - p_r [Pa].
  double span(const ValveDescription &valve);
  /// Each fraction times `scale'.
  std::vector<double> scaled(const std::vector<double> &fractions, double scale);
  /// The nozzle's gaps in the order the stage's chain takes them, from the null gap outwards: the
  /// gap fraction nearest 1, the smaller ones downwards, then the larger ones upwards, each with the
  /// index of the gap whose first case it starts from (-1: none).
  std::vector<std::pair<std::size_t, int>> gap_order(const std::vector<double> &fractions);
  const char *model_name(Turbulence t);
  /// <output>/flow
  std::string flow_directory(const ValveDescription &valve);
  /// The VTU file name of a case.
  std::string vtu_name(PilotGeometry g, double T, double h, double dp);
  /// `Output/Flow fields' asks for the VTU of the cases at temperature T.
  bool writes_fields(const ValveDescription &valve, double T);

  /// One continuation chain at a temperature: the cases of one geometry (and gap), created per
  /// flow model as needed, each new one starting from the last converged fields.
  class Chain
  {
  public:
    Chain(const ValveDescription &valve_, PilotGeometry g, double T)
      : valve(valve_)
      , settings(pilot_field_settings(valve_))
      , kind(g)
      , conditions(pilot_field_case(valve_, T))
      , closed_forms(valve_, T)
    {}

    /// Solves the case of gap h (nozzle) at dp with the model the valve description asks for,
    /// from `start' if given (another gap's fields), else from the chain's last fields. Returns the
    /// record; keeps the fields if it converged.
    std::vector<double> solve(double h, double dp, const std::optional<FlowFields> &start = std::nullopt);

    const std::optional<FlowFields> &last_fields() const { return last; }

    /// The chain's last converged state: its fields, their flow model and pressure level.
    struct State
    {
      FlowFields fields;
      Turbulence model;
      double pressure_difference;
      template <class Archive>
      void serialize(Archive &archive, unsigned int)
      {
        archive &fields &model &pressure_difference;
      }
    };
    std::optional<State> state() const
    {
      return last ? std::optional<State>(State{*last, last_model, last_dp}) : std::nullopt;
    }
    /// Goes on from another chain's state as if this chain had converged to it (the next case
    /// continues from it, and a failing one is retried through the geometric mean of the levels).
    void resume(const State &s);
    /// A converged state of another flow model (another chain's, at another temperature) that a
    /// case switching to that model starts from, instead of the fields of the model it leaves:
    /// k-epsilon seeded on laminar fields spends 1 000-1 500 iterations while its eddy viscosity
    /// builds up, from another temperature's k-epsilon fields it needs the iterations of a pressure
    /// step (doc/performance.md, issue 28). Used by the first such switch only; the one offered
    /// last per model stands.
    void offer(const State &s) { offered[s.model] = s.fields; }

  private:
    /// The case by the retry ladder (flow/pilot/pilot_field_retry.h, defined in pilot_field_retry.cc):
    /// retry_ladder's attempts for model t in `slot', run by run_ladder until one converges. If none
    /// does, the state nearest a steady state (FailedAttempts) is left in `slot' and written to the
    /// case's VTU, and the outcome says stalled (its time average marches from that state) or, if no
    /// attempt left a state, failed.
    CaseOutcome solve_with_retry(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp,
                                 bool started_elsewhere);
    /// Attempt::from_rest_in_smaller_steps: the case from rest (laminar start-up) in a new `slot',
    /// with half the steps of `Field solution/Continuation ratio' (in the logarithm) for this solve.
    AttemptOutcome solve_from_rest(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp);
    /// Attempt::from_k_epsilon_solution: the case solved with the two-layer k-epsilon (on its own
    /// ladder, from the chain's last fields if they are model t's), and model t started from that
    /// solution at the same pressure level in a new `slot'. Its iterations include k-epsilon's. If
    /// k-epsilon's solve fails, `slot' is left as it was (failed_without_state); if model t diverges,
    /// `slot' holds model t set afresh into k-epsilon's solution (diverged_from_start).
    AttemptOutcome solve_from_k_epsilon(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp);
    /// A case whose steady iteration stalled (`why'): its time average into `record'
    /// (flow/pilot/pilot_field_time_average.h); false, with a warning, if that fails too or the uncertainty
    /// of its mean is beyond `Time average/Uncertainty limit' (the average is then recorded,
    /// not used). A used
    /// average's mean fields go to the case's VTU.
    bool time_average_of(PilotField &field, double dp, const std::string &where, const std::string &why,
                         std::vector<double> &record);

    const ValveDescription &valve;
    PilotFieldSettings settings; ///< what the cases read of the valve
    PilotGeometry kind;
    PilotFieldCase conditions;
    PilotClosedForms closed_forms;
    double current_gap = -1;
    std::map<Turbulence, std::unique_ptr<PilotField>> cases;
    std::optional<FlowFields> last;
    Turbulence last_model = Turbulence::laminar;
    double last_dp = 0; ///< the pressure level of `last'
    std::map<Turbulence, FlowFields> offered; ///< offer(): other models' states to switch to
    /// the VTU of the case being solved, if any (`Output/Flow fields'): its last iterate if it
    /// fails, its mean fields if its time average stands for it
    std::string failure_output;
  };

  /// flow/<geometry>_cases<variant>.csv and the .pvd collection of the VTU files written (rank 0).
  void write_case_summary(const ValveDescription &valve, PilotGeometry g, const CaseRows &records,
                          const std::string &variant = "");
  /// The warnings and notes of a geometry's cases on stderr (rank 0): not converged, beyond the
  /// verified range, cavitating.
  void report_counts(const char *what, const CaseRows &records, bool valve_cavitation);
  /// The nozzle table's note on its discretisation error at the valve's mesh resolution, from the
  /// errors bench/bench_mesh_convergence measured on RV-1 (doc/benchmarks/nozzle_mesh_errors.csv,
  /// compiled in): their range at that resolution, or that none was measured there.
  std::string nozzle_mesh_error_note(const ValveDescription &valve);
  /// The tables from the records (in increasing temperature), with the exact no-flow rows (flag 3).
  Table fixed_orifice_table(const ValveDescription &valve, const CaseRows &records);
  Table nozzle_flapper_table(const ValveDescription &valve, const CaseRows &records);
} // namespace servodrift::flow
