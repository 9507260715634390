#pragma once
// The valve's equations (valve_equations.h) as an initial value problem y' = F(y, i_command(t)) in
// state-vector form, and what every dynamic analysis shares: the scale of each state, the parts a
// closed-form check holds still, the command signal (current drive: the coil current; voltage drive:
// u = R_c(T0) i_command, an amplifier set up at the reference temperature), the Jacobian for the
// linearisation, and a CVODE integrator of the whole.
#include "common/parameters/dynamics.h"
#include "system/time_integrator.h"
#include "system/valve_equations.h"

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace servodrift::system
{
  /// Parts held still: the subsystems of the closed-form checks (their rates are zero).
  struct HeldParts
  {
    bool flapper = false;           ///< theta, dtheta/dt
    bool control_pressures = false; ///< p_L, p_R
    bool spool = false;             ///< x_v, dx_v/dt
    bool brake_volume = false;      ///< p_B: an external brake port holds it at the port's pressure (FMU)
  };

  /// The groups of states after which a mode is named.
  enum class StateGroup
  {
    armature_flapper,
    pilot_pressures,
    spool,
    brake_volume,
    coil
  };
  constexpr std::size_t n_state_groups = 5;
  const char *to_string(StateGroup group);
  StateGroup group_of_state(std::size_t k);

  class ValveDynamics;

  /// CVODE on the deviation z = y - origin from a state near which the valve moves (the static
  /// operating point it starts from): the error control is then relative to the motion, not to the
  /// bias (a 1 kPa ripple on a 10 MPa brake pressure is resolved to rtol of 1 kPa). The interface
  /// speaks in whole states y.
  class ValveIntegrator
  {
  public:
    ValveIntegrator(const ValveDynamics &dynamics, std::function<double(double t)> command,
                    const DynamicsParameters &parameters, const std::string &context, std::vector<double> origin);
    void start(double t0, const std::vector<double> &y0);
    /// See TimeIntegrator::integrate; y() and interpolate() are whole states.
    double integrate(double t_end, const std::function<bool(double t_previous, double t)> &on_step);
    const std::vector<double> &advance_to(double t);
    std::vector<double> interpolate(double t) const;
    const std::vector<double> &y() const { return y_now; }
    double time() const { return integrator->time(); }
    TimeIntegrator::Statistics statistics() const { return integrator->statistics(); }

  private:
    std::vector<double> origin, y_now;
    std::unique_ptr<TimeIntegrator> integrator;
    void update();
  };

  class ValveDynamics
  {
  public:
    /// `amplifier_resistance' = R_c(T0): the voltage drive's u per ampere of command [Ohm].
    ValveDynamics(const ValveEquations &equations, double amplifier_resistance, double rated_current,
                  HeldParts held = {});

    /// 7 states, 8 under voltage drive (the coil current)
    std::size_t size() const { return n; }
    std::vector<double> vector_of(const ValveState &state) const;
    /// The state of a vector; under current drive the coil current is the command.
    ValveState state_of(const double *y, double command_current) const;
    /// Scale of each state: x0/r, x0/r w_ref, p_s - p_r (twice), stroke, stroke w_ref, p_s - p_r,
    /// rated current, with w_ref = sqrt(K_a/J_a).
    const std::vector<double> &scales() const { return scale; }
    /// The largest |y_k - z_k|/scale_k.
    double scaled_distance(const std::vector<double> &y, const std::vector<double> &z) const;

    ValveInput input(double command_current) const;
    /// The coil current that flows at steady state for a command (voltage drive: R_c(T0)/R_c(T) of it).
    double steady_current(double command_current) const;
    /// F(y, i_command)
    void rates(const double *y, double command_current, double *ydot) const;
    /// A = dF/dy and B = dF/di_command at (y, i_command), central differences with steps of 1e-6 of
    /// each state's scale (the tables are interpolated with continuous first derivatives).
    void linearise(const std::vector<double> &y, double command_current, Eigen::MatrixXd &A, Eigen::VectorXd &B) const;

    /// A CVODE integrator of y' = F(y, command(t)) about `origin' with the tolerances of the
    /// Dynamics subsection (absolute tolerance per state scale); `context' names the case in errors.
    std::unique_ptr<ValveIntegrator> integrator(std::function<double(double t)> command,
                                                const DynamicsParameters &parameters, const std::string &context,
                                                const std::vector<double> &origin) const;

    const ValveEquations &equations() const { return eq; }

  private:
    ValveEquations eq;
    double amplifier_resistance;
    double rated_current;
    HeldParts held;
    std::size_t n;
    std::vector<double> scale;
  };
} // namespace servodrift::system
