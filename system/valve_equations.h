#pragma once
// The valve's equations, written once (model.md E29-E37, 1.20, C14): the element laws (flows,
// forces, torques) and the right-hand side of the states of 1.20, at one uniform temperature. The
// static model (valve_model.cc) solves these equations at zero rates; the dynamic analyses integrate
// and linearise the same right-hand side. Only the coefficient tables and the valve description go
// in; nothing here knows which level made a table (D13).
#include "common/pilot_closed_forms.h"
#include "common/torque_motor_circuit.h"
#include "common/valve_description.h"
#include "system/stage_tables.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>

namespace servodrift::system
{
  /// The two sides of the pilot bridge: left is the side of p_L (model.md 1.12).
  enum Side : std::size_t
  {
    left = 0,
    right = 1
  };

  /// How this valve is built: the assembly offsets of E39 (spring-tube rest angle, magnetic null,
  /// hydraulic null) and, for an asymmetric valve, the left and right build deviations of the pilot
  /// bridge and the torque motor's mismatch (issue 25). Default: the ideal symmetric valve.
  struct Offsets
  {
    double spring_tube_rest_angle = 0;   ///< theta_s [rad]
    double magnetic_null = 0;            ///< theta_m [rad]
    double hydraulic_null = 0;           ///< x_n [m]
    std::array<SideDeviations, 2> sides; ///< left, right deviations from the tables' geometry
    MagneticMismatch magnetic;           ///< mapped to a magnetic null, K_m and K_t through E3
  };

  /// The states of model.md 1.20 (SI, gauge pressures).
  struct ValveState
  {
    double angle = 0;              ///< theta [rad]
    double angular_velocity = 0;   ///< dtheta/dt [rad/s]
    double left_pressure = 0;      ///< p_L [Pa]
    double right_pressure = 0;     ///< p_R [Pa]
    double spool_displacement = 0; ///< x_v [m]
    double spool_velocity = 0;     ///< dx_v/dt [m/s]
    double brake_pressure = 0;     ///< p_B [Pa]
    double coil_current = 0;       ///< i [A]: a state under voltage drive, else the input current
  };
  /// The members in state-vector order; the coil current is the last and a state only under
  /// voltage drive.
  inline constexpr std::array<double ValveState::*, 8> state_members = {
    &ValveState::angle,          &ValveState::angular_velocity,   &ValveState::left_pressure,
    &ValveState::right_pressure, &ValveState::spool_displacement, &ValveState::spool_velocity,
    &ValveState::brake_pressure, &ValveState::coil_current};
  inline constexpr std::array<const char *, 8> state_names = {
    "angle[rad]",          "angular_velocity[rad/s]", "left_pressure[Pa]", "right_pressure[Pa]",
    "spool_displacement[m]", "spool_velocity[m/s]",   "brake_pressure[Pa]", "coil_current[A]"};

  /// What drives the valve: the control current (current drive) or the coil voltage (voltage drive).
  struct ValveInput
  {
    double current = 0; ///< [A]
    double voltage = 0; ///< [V]
  };

  /// The two metering edges of the spool (E36 with the lap leakage and the tanh blend E20, C14) and
  /// their steady flow forces (E35), at a spool position and brake pressure.
  struct MeteringEdges
  {
    double supply_flow; ///< supply -> brake port [m^3/s]
    double return_flow; ///< brake port -> return [m^3/s]
    double supply_force; ///< flow force of the supply edge, >= 0, pushing the spool to close it (-x) [N]
    double return_force; ///< flow force of the return edge, >= 0, pushing the spool to close it (+x) [N]
  };

  class ValveEquations
  {
  public:
    ValveEquations(const ValveDescription &valve, const StageFunctions &functions, double temperature,
                   const Offsets &offsets);

    // --- armature and flapper (E29, E30) -----------------------------------------------------
    /// x_f = r theta - x_n (E30 with the hydraulic null of E39) [m]
    double flapper_displacement(double angle) const { return r * angle - offsets_.hydraulic_null; }
    /// The armature angle at which the flapper sits at x_f [rad]
    double angle_of(double flapper_displacement) const
    {
      return (flapper_displacement + offsets_.hydraulic_null) / r;
    }
    /// T_em(theta - theta_m, i) from the torque_motor table (E29 with E39) [N*m]
    double motor_torque(double angle, double current) const;
    /// dT_em/di: the torque constant at (theta, i), and by reciprocity the back-EMF constant [N*m/A]
    double torque_per_current(double angle, double current) const;
    /// Torque of the nozzle contacts: a stiff, damped stop at each nozzle, never pulling [N*m]
    double nozzle_contact_torque(double angle, double angular_velocity) const;
    /// Everything E29 puts on the armature but inertia and B_a: T_em - K_a (theta - theta_s)
    /// - r (F_L - F_R) + contact [N*m]
    double net_torque(double angle, double angular_velocity, double left_pressure, double right_pressure,
                      double current) const;

    // --- pilot stage (E31-E33, E23) ----------------------------------------------------------
    /// The nozzle-flapper gaps x0_L - x_f and x0_R + x_f at an armature angle, floored at 0 (a
    /// flapper on a nozzle closes it) [m]
    std::array<double, 2> gaps(double angle) const { return gaps_at(flapper_displacement(angle)); }
    std::array<double, 2> gaps_at(double flapper_displacement) const;
    /// E31: Q_0 through one side's fixed orifice for dp = p_s - p (signed square root, laminar near 0) [m^3/s]
    double orifice_flow(Side side, double pressure_difference) const;
    /// E32: Q_N through one side's nozzle-flapper gap for dp = p - p_r [m^3/s]
    double nozzle_flow(Side side, double gap, double pressure_difference) const;
    /// E23 / table: force of one side's jet on the flapper, with E23's change for this side's own
    /// bore and flow where the side is built off the tables' geometry [N]
    double flapper_force(Side side, double gap, double pressure_difference) const;
    /// E33's numerator: net inflow Q_0 - Q_N - (spool end's volume rate) into a control cavity [m^3/s]
    double cavity_inflow(Side side, double gap, double pressure, double volume_rate) const;

    // --- spool stage (E35-E37) -----------------------------------------------------------------
    MeteringEdges metering(double spool_displacement, double brake_pressure) const;
    /// E36: net flow into the brake port (E37 with Q_load = 0) [m^3/s]
    double brake_inflow(double spool_displacement, double brake_pressure) const;
    /// Everything E35 puts on the spool but m_v a and B_v v: control force, pressure feedback,
    /// spring, flow forces and the stroke stops [N]
    double spool_net_force(double spool_displacement, double spool_velocity, double control_pressure_difference,
                           double brake_pressure) const;

    // --- the right-hand side -----------------------------------------------------------------
    /// d/dt of every state (E29, E33, E35, E37 and the coil); the coil current's rate is 0 under
    /// current drive, where the input sets it.
    ValveState rates(const ValveState &state, const ValveInput &input) const;
    /// The current that flows: the state under voltage drive, else the input [A]
    double current(const ValveState &state, const ValveInput &input) const
    {
      return voltage_drive_ ? state.coil_current : input.current;
    }
    /// The current that a voltage drives at steady state: u/R_c(T) [A]
    double steady_current_of_voltage(double voltage) const { return voltage / coil_resistance; }

    // --- values at this temperature that the analyses need -------------------------------------
    double temperature() const { return T; }
    bool voltage_drive() const { return voltage_drive_; }
    const Offsets &offsets() const { return offsets_; }
    /// The same valve with another hydraulic null x_n (the null adjustment) [m]
    ValveEquations with_hydraulic_null(double x_n) const
    {
      ValveEquations e = *this;
      e.offsets_.hydraulic_null = x_n;
      return e;
    }
    double null_gap() const { return x0; }                           ///< nominal x0(T) [m]
    double null_gap(Side side) const { return side_gap[side]; }      ///< this side's x0(T) [m]
    /// theta_m plus the magnetic null of the motor's mismatch at T (E3) [rad]
    double magnetic_null() const { return magnetic_null_; }
    double pivot_to_nozzle_distance() const { return r; }            ///< [m]
    double supply_pressure() const { return p_s; }                   ///< [Pa]
    double return_pressure() const { return p_r; }                   ///< [Pa]
    double spring_stiffness() const { return K_a; }                  ///< K_a(T) [N*m/rad]
    double overlap() const { return x_ov; }                          ///< [m]
    double stroke_limit() const { return stroke; }                   ///< [m]
    double control_area() const { return A_v; }                      ///< A_v(T) [m^2]
    double feedback_area() const { return A_fb; }                    ///< A_fb(T) [m^2]
    double bulk_modulus() const { return beta; }                     ///< beta_e(T) [Pa]
    double control_cavity_volume() const { return V_0; }             ///< [m^3]
    double brake_side_volume() const { return V_B; }                 ///< V_B or the port's [m^3]
    double spool_damping() const { return B_v; }                     ///< B_v(T) [N*s/m]
    double inertia() const { return J_a; }                           ///< [kg*m^2]
    double armature_damping() const { return B_a; }                  ///< [N*m*s/rad]
    double spool_mass() const { return m_v; }                        ///< [kg]
    double coil_inductance() const { return L_c; }                   ///< [H]
    const std::vector<double> &table_currents() const { return f.torque.axis(2); } ///< [A]
    /// The same valve with one side's pilot stage read from tables of its own (a side tabulated at
    /// its own geometry; the tables' axes must be the nominal tables')
    ValveEquations with_side_tables(Side side, const StageFunctions &side_functions) const
    {
      ValveEquations e = *this;
      e.pilot_tables[side] = &side_functions;
      return e;
    }
    /// Both halves of the pilot bridge the same: the same deviations and the same tables
    bool symmetric_bridge() const;
    /// true once a query went beyond the flow tables' pressure range (constant C_d beyond)
    bool left_tables() const { return table_exceeded; }
    void forget_table_excursions() const { table_exceeded = false; }

  private:
    const StageFunctions &f;
    Offsets offsets_;
    double T;
    bool voltage_drive_;
    double p_s, p_r, r, x0, K_a, J_a, B_a;
    // asymmetric valve (issue 25): per side, and the motor's mismatch mapped through E3
    std::array<double, 2> side_gap, orifice_factor, nozzle_factor;
    /// A side built off the tables' bores carries the table's flows and jet force by the bore
    /// tables' ratios where the flow stage made them, else by the closed forms' ratio at its own
    /// and the tables' bores (E21, E22) and E23's change (doc/method.md "Asymmetric valve"); a
    /// discharge factor by E23's momentum change. The closed forms at the tables' geometry and at
    /// each side's; null where unused.
    std::shared_ptr<const PilotClosedForms> nominal_forms;
    std::array<std::shared_ptr<const PilotClosedForms>, 2> side_forms;
    std::array<bool, 2> orifice_bore_deviates{}, nozzle_bore_deviates{}, side_deviates{};
    std::array<double, 2> orifice_deviation{}, nozzle_deviation{}; ///< D' - D of each side [m]
    std::array<const StageFunctions *, 2> pilot_tables; ///< each side's pilot tables (the nominal: &f)
    double magnetic_null_;
    bool motor_mismatch;
    double magnetic_spring_ratio = 1, torque_constant_ratio = 1; // K_m'/K_m, K_t'/K_t at T
    double contact_stiffness, contact_damping;     // at the nozzle axis [N/m], [N*s/m]
    double orifice_dp_max, nozzle_dp_max, gap_max; // table ranges
    double A_v, A_fb, V_0, beta, V_B, m_v, B_v, k_s, F_s0, W, x_ov, stroke, C_dv, jet_cosine;
    double stop_stiffness, stop_damping, leak_coefficient, minimum_leak_length, transition_number;
    double rho, nu;
    double coil_resistance, L_c;
    mutable bool table_exceeded = false;

    /// The tables' flows of one side at |dp| (and a gap in the table) [m^3/s]
    double tabulated_orifice_flow(Side side, double pressure_difference) const;
    double tabulated_nozzle_flow(Side side, double gap, double pressure_difference) const;
    /// Q(side's bore)/Q(tables' bore) by the bore tables or the closed forms (E21 or E22); 1 for
    /// the tables' bore
    double orifice_bore_ratio(Side side, double pressure_difference) const;
    double nozzle_bore_ratio(Side side, double gap, double pressure_difference) const;
    /// The same ratio of the flapper force by the bore table (empty without one)
    std::optional<double> force_bore_ratio(Side side, double gap, double pressure_difference) const;

    /// One metering edge of opening `opening' (> 0 open) and pressure difference dp across it.
    std::array<double, 2> edge(double opening, double pressure_difference) const;
  };
} // namespace servodrift::system
