#pragma once
// The static whole-valve model (model.md 1.12-1.19): the equations of valve_equations.h at zero
// rates, driven only by the coefficient tables.
//
// At zero rates with the brake port blocked no oil flows into the control cavities or the brake
// volume, so the equations form a cascade of scalar, monotone problems, each solved on a bracket
// (TOMS 748) rather than by a coupled Newton iteration that could leave the physical range:
//   1. bridge (E33 at rest, E31 = E32): for a flapper position, each control pressure;
//   2. torque balance (E29 at rest, offsets E39, D8): one equation in the armature angle, bracketed
//      by the two nozzle contacts; no sign change there means the flapper is pressed onto a nozzle
//      (saturation), where it sinks into the contact's stiffness;
//   3. spool (E35 at rest): the force balance in x_v, with the brake pressure of each x_v from the
//      brake port's flow balance (E36, E37 at rest); past the stroke limits the stops hold it.
#include "common/valve_description.h"
#include "system/stage_tables.h"
#include "system/valve_equations.h"

#include <optional>
#include <string>

namespace servodrift::system
{
  enum class FlapperState
  {
    free,
    on_left_nozzle,
    on_right_nozzle
  };
  enum class SpoolState
  {
    on_negative_stop, ///< x_v at or past -stroke limit
    vented,           ///< brake port open to return, p_B = p_r (plus the supply land's leakage)
    regulating,       ///< in the lap; p_B set by the lap-leakage divider and the force balance
    at_supply,        ///< brake port open to supply, p_B = p_s (minus the return land's leakage)
    on_positive_stop  ///< x_v at or past +stroke limit
  };
  const char *to_string(FlapperState state);
  const char *to_string(SpoolState state);

  struct BridgeState
  {
    double left_gap, right_gap;          ///< x0 -+ x_f [m]
    double left_pressure, right_pressure; ///< p_L, p_R [Pa]
    double left_flow, right_flow;        ///< nozzle flows [m^3/s]
    double left_force, right_force;      ///< flapper forces of the two jets [N]
  };

  struct SpoolSolution
  {
    double displacement;  ///< x_v [m]
    double brake_pressure; ///< p_B, gauge [Pa]
    SpoolState state;
  };

  struct OperatingPoint
  {
    double temperature, current;
    double angle;                ///< theta [rad]
    double flapper_displacement; ///< x_f = r theta - x_n [m]
    BridgeState bridge;
    SpoolSolution spool;
    FlapperState flapper;
    double control_pressure_difference() const { return bridge.left_pressure - bridge.right_pressure; }
    /// The state of model.md 1.20 at this point: every rate zero.
    ValveState state() const;
  };

  class ValveModel
  {
  public:
    ValveModel(const ValveDescription &valve, const StageTables &tables);
    /// With the interpolants of tables already read (a calibration evaluates many descriptions).
    ValveModel(const ValveDescription &valve, const StageFunctions &functions);

    /// The valve's equations at T with these offsets: what every analysis evaluates.
    ValveEquations equations(double temperature, const Offsets &offsets = {}) const;

    /// Bridge with the flapper at x_f (E31, E32) and the flapper forces (E23 / table) [blocked spool].
    BridgeState bridge(double temperature, double flapper_displacement) const;
    BridgeState bridge(const ValveEquations &equations, double flapper_displacement) const;
    /// Static spool with blocked brake port for a control pressure difference p_L - p_R (E35, E36).
    SpoolSolution spool(double temperature, double control_pressure_difference) const;
    SpoolSolution spool(const ValveEquations &equations, double control_pressure_difference) const;
    /// The static operating point (E29 static with E39 offsets).
    OperatingPoint solve(double temperature, double current, const Offsets &offsets) const;
    OperatingPoint solve(const ValveEquations &equations, double current) const;

    /// Hydraulic null x_n that puts the pilot at null (p_L = p_R) at T0 and i = 0 for the other
    /// offsets and deviations of `offsets': the manufacturer's null adjustment (D8 "nulled at reference").
    double nulling_hydraulic_null(const Offsets &offsets) const;
    /// The same for the valve's equations at T0 (`equations(T0, offsets)' or a variant of them).
    double nulling_hydraulic_null(const ValveEquations &equations_at_reference) const;
    /// The flapper position x_f* of the pilot null, p_L = p_R (0 for a symmetric bridge) [m].
    double null_flapper_displacement(const ValveEquations &equations) const;
    /// The current that restores the pilot null (p_L = p_R) at T; empty if it lies outside the
    /// torque_motor table's current range.
    std::optional<double> null_shift_current(double temperature, const Offsets &offsets) const;
    std::optional<double> null_shift_current(const ValveEquations &equations) const;
    /// The null-shift current, or where none lies within the torque_motor table, the table's end
    /// current on the side the balance points to, flagged (a bound on the true value) [A].
    struct NullShift
    {
      double current;
      bool beyond_table;
    };
    NullShift null_shift(const ValveEquations &equations) const;
    /// The valve as described: `Offsets' and `Asymmetry' of the valve description.
    Offsets described_offsets() const;
    /// Offsets of a valve with assembly deviation theta_d (D8: target and nulling convention).
    Offsets offsets_for_deviation(double deviation_angle) const;

    /// Flow-force stiffness K_f = d(F_L - F_R)/dx_f at null (E24), by central differences.
    double flow_force_stiffness(double temperature) const;
    /// Null gap x0(T) (2.3) [m].
    double null_gap(double temperature) const;

    const StageFunctions &functions() const { return f; }
    const ValveDescription &description() const { return valve; }

  private:
    ValveDescription valve;
    StageFunctions f;
  };
} // namespace servodrift::system
