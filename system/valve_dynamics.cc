#include "system/valve_dynamics.h"

#include <algorithm>
#include <cmath>

namespace servodrift::system
{
  const char *to_string(StateGroup g)
  {
    switch (g)
      {
        case StateGroup::armature_flapper: return "armature-flapper";
        case StateGroup::pilot_pressures: return "pilot pressures";
        case StateGroup::spool: return "spool";
        case StateGroup::brake_volume: return "brake volume";
        case StateGroup::coil: return "coil";
      }
    return "?";
  }

  StateGroup group_of_state(std::size_t k)
  {
    static const StateGroup groups[] = {StateGroup::armature_flapper, StateGroup::armature_flapper,
                                        StateGroup::pilot_pressures,  StateGroup::pilot_pressures,
                                        StateGroup::spool,            StateGroup::spool,
                                        StateGroup::brake_volume,     StateGroup::coil};
    return groups[k];
  }

  ValveDynamics::ValveDynamics(const ValveEquations &equations, double amplifier_resistance_, double rated_current_,
                               HeldParts held_)
    : eq(equations)
    , amplifier_resistance(amplifier_resistance_)
    , rated_current(rated_current_)
    , held(held_)
    , n(equations.voltage_drive() ? 8 : 7)
  {
    const double angle = eq.null_gap() / eq.pivot_to_nozzle_distance();
    const double w_ref = std::sqrt(eq.spring_stiffness() / eq.inertia());
    const double p = eq.supply_pressure() - eq.return_pressure(), x = eq.stroke_limit();
    scale = {angle, angle * w_ref, p, p, x, x * w_ref, p, rated_current};
    scale.resize(n);
  }

  std::vector<double> ValveDynamics::vector_of(const ValveState &s) const
  {
    std::vector<double> y(n);
    for (std::size_t k = 0; k < n; ++k)
      y[k] = s.*state_members[k];
    return y;
  }

  ValveState ValveDynamics::state_of(const double *y, double command) const
  {
    ValveState s;
    for (std::size_t k = 0; k < n; ++k)
      s.*state_members[k] = y[k];
    if (!eq.voltage_drive())
      s.coil_current = command;
    return s;
  }

  double ValveDynamics::scaled_distance(const std::vector<double> &y, const std::vector<double> &z) const
  {
    double d = 0;
    for (std::size_t k = 0; k < n; ++k)
      d = std::max(d, std::abs(y[k] - z[k]) / scale[k]);
    return d;
  }

  ValveInput ValveDynamics::input(double command) const
  {
    return eq.voltage_drive() ? ValveInput{0.0, amplifier_resistance * command} : ValveInput{command, 0.0};
  }

  double ValveDynamics::steady_current(double command) const
  {
    return eq.voltage_drive() ? eq.steady_current_of_voltage(amplifier_resistance * command) : command;
  }

  void ValveDynamics::rates(const double *y, double command, double *ydot) const
  {
    const ValveState d = eq.rates(state_of(y, command), input(command));
    for (std::size_t k = 0; k < n; ++k)
      ydot[k] = d.*state_members[k];
    if (held.flapper)
      ydot[0] = ydot[1] = 0;
    if (held.control_pressures)
      ydot[2] = ydot[3] = 0;
    if (held.spool)
      ydot[4] = ydot[5] = 0;
    if (held.brake_volume)
      ydot[6] = 0;
  }

  void ValveDynamics::linearise(const std::vector<double> &y, double command, Eigen::MatrixXd &A,
                                Eigen::VectorXd &B) const
  {
    A.resize(n, n);
    B.resize(n);
    std::vector<double> plus(n), minus(n), z = y;
    for (std::size_t k = 0; k < n; ++k)
      {
        const double h = 1e-6 * scale[k];
        z[k] = y[k] + h;
        rates(z.data(), command, plus.data());
        z[k] = y[k] - h;
        rates(z.data(), command, minus.data());
        z[k] = y[k];
        for (std::size_t j = 0; j < n; ++j)
          A(j, k) = (plus[j] - minus[j]) / (2 * h);
      }
    // within the torque table's currents: one-sided at its ends (the rated current may be one)
    const auto &currents = eq.table_currents();
    const double h = 1e-6 * rated_current;
    const double hi = std::min(command + h, currents.back()), lo = std::max(command - h, currents.front());
    rates(y.data(), hi, plus.data());
    rates(y.data(), lo, minus.data());
    for (std::size_t j = 0; j < n; ++j)
      B(j) = (plus[j] - minus[j]) / (hi - lo);
  }

  std::unique_ptr<ValveIntegrator> ValveDynamics::integrator(std::function<double(double)> command,
                                                             const DynamicsParameters &p, const std::string &context,
                                                             const std::vector<double> &origin) const
  {
    return std::make_unique<ValveIntegrator>(*this, std::move(command), p, context, origin);
  }

  ValveIntegrator::ValveIntegrator(const ValveDynamics &dynamics, std::function<double(double)> command,
                                   const DynamicsParameters &p, const std::string &context, std::vector<double> origin_)
    : origin(std::move(origin_))
    , y_now(origin)
  {
    TimeIntegrator::Settings settings;
    settings.relative_tolerance = p.relative_tolerance;
    settings.maximum_steps = p.maximum_steps;
    settings.describe_component = [](std::size_t k) -> std::string {
      // the state (model.md 1.20) and the entries that set how fast it can move
      switch (k)
        {
          case 0:
          case 1: return "the armature (`Armature/Nozzle contact stiffness', `Inertia', `Damping')";
          case 2:
          case 3: return "a control pressure (`Pilot stage/Control cavity volume', the oil's bulk modulus)";
          case 4:
          case 5: return "the spool (`Spool/Stop stiffness', `Mass', `Laminar transition number')";
          case 6: return "the brake pressure (`Spool/Minimum leak length', `Radial clearance', `Brake volume')";
          default: return "the coil current (`Torque motor/Coil inductance')";
        }
    };
    for (double s : dynamics.scales())
      settings.absolute_tolerances.push_back(p.absolute_tolerance * s);
    // Forward differences on the whole state, with steps of 1e-7 of max(|y_k|, scale_k): CVODE's own
    // steps would follow |z_k|, which is 0 at the origin, and vanish below the rounding of y_k.
    const std::size_t n = origin.size();
    settings.jacobian = [&dynamics, this, command, n, y = std::vector<double>(n), f = std::vector<double>(n)](
                          double t, const double *z, const double *fz, double *J) mutable {
      for (std::size_t k = 0; k < n; ++k)
        y[k] = origin[k] + z[k];
      const double i = command(t);
      for (std::size_t k = 0; k < n; ++k)
        {
          const double saved = y[k];
          y[k] += 1e-7 * std::max(std::abs(saved), dynamics.scales()[k]);
          const double h = y[k] - saved; // the step as represented
          dynamics.rates(y.data(), i, f.data());
          y[k] = saved;
          for (std::size_t j = 0; j < n; ++j)
            J[k * n + j] = (f[j] - fz[j]) / h;
        }
    };
    auto rhs = [&dynamics, this, command = std::move(command), y = std::vector<double>(n)](
                 double t, const double *z, double *ydot) mutable {
      for (std::size_t k = 0; k < y.size(); ++k)
        y[k] = origin[k] + z[k];
      dynamics.rates(y.data(), command(t), ydot);
    };
    integrator = std::make_unique<TimeIntegrator>(n, std::move(rhs), settings, context);
  }

  void ValveIntegrator::update()
  {
    const auto &z = integrator->y();
    for (std::size_t k = 0; k < origin.size(); ++k)
      y_now[k] = origin[k] + z[k];
  }

  void ValveIntegrator::start(double t0, const std::vector<double> &y0)
  {
    std::vector<double> z(y0.size());
    for (std::size_t k = 0; k < z.size(); ++k)
      z[k] = y0[k] - origin[k];
    integrator->start(t0, z);
    update();
  }

  double ValveIntegrator::integrate(double t_end, const std::function<bool(double, double)> &on_step)
  {
    return integrator->integrate(t_end, [&](double t_previous, double t) {
      update();
      return on_step(t_previous, t);
    });
  }

  const std::vector<double> &ValveIntegrator::advance_to(double t)
  {
    integrator->advance_to(t);
    update();
    return y_now;
  }

  std::vector<double> ValveIntegrator::interpolate(double t) const
  {
    std::vector<double> y = integrator->interpolate(t);
    for (std::size_t k = 0; k < y.size(); ++k)
      y[k] += origin[k];
    return y;
  }
} // namespace servodrift::system
