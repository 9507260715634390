#pragma once
// Step responses of the nonlinear valve (issue 23): at t = 0 the command current jumps from one
// value to another, starting from the static operating point of the first; CVODE integrates the
// valve's equations until they settle. For p_B, x_v and x_f: rise time 10-90 %, overshoot and the
// 2 % settling time, each refined within the integrator's step on its interpolating polynomial.
#include "common/parameters/dynamics.h"
#include "system/time_integrator.h"
#include "system/valve_dynamics.h"
#include "system/valve_model.h"

#include <array>
#include <optional>
#include <vector>

namespace servodrift::system
{
  struct StepMetrics
  {
    double initial = 0, final = 0;       ///< the static values before and after the step [SI]
    std::optional<double> rise_time;     ///< from 10 % to 90 % of the change [s]
    double overshoot = 0;                ///< largest excursion beyond the final value, % of the change
    std::optional<double> settling_time; ///< last entry into the band of 2 % of the change [s]
  };

  /// The outputs of a step response, in the order of StepResponse::metrics.
  inline constexpr std::array<const char *, 3> step_outputs = {"brake_pressure", "spool_displacement",
                                                               "flapper_displacement"};

  struct StepResponse
  {
    double from_current = 0, to_current = 0; ///< command [A]
    double duration = 0;                     ///< simulated time [s]
    std::vector<double> times;               ///< samples: uniform over [0, duration] and over its first 10 ms [s]
    std::vector<ValveState> states;          ///< at `times'
    std::array<StepMetrics, 3> metrics;      ///< p_B, x_v, x_f
    double final_distance = 0;               ///< scaled distance of the last state from the static point [1]
    bool flapper_contact = false;            ///< the flapper touched a nozzle
    bool spool_on_stop = false;              ///< the spool reached a stroke limit
    bool left_tables = false;           ///< a pressure went beyond the flow tables (constant C_d)
    TimeIntegrator::Statistics statistics;
  };

  /// The simulated time of a step to `to_current': `Dynamics/Step duration', or 8 time constants of
  /// the slowest mode at the end point (at least 20 ms, at most `longest').
  double step_duration(const ValveModel &model, const ValveDynamics &dynamics, double to_current,
                       const DynamicsParameters &parameters, double longest = 10);

  /// From the static point at `from_current' to the command `to_current'.
  StepResponse step_response(const ValveModel &model, const ValveDynamics &dynamics, double from_current,
                             double to_current, const DynamicsParameters &parameters, unsigned int samples);

  /// The longest start-up [s]: at -55 degC RV-1's spool and brake-volume loop decays over 5.5 s, and
  /// a start-up is read for the time it takes to regulate, so it runs until that loop has settled.
  constexpr double longest_start_up = 60;

  /// The start-up from rest (every pressure at return, armature and spool centred: a valve soaked at
  /// the equations' temperature) with the supply and the command `to_current' applied at t = 0: the
  /// cold-soak start of issue 65. from_current is 0; the metrics' initial values are the rest state's.
  StepResponse start_up_response(const ValveModel &model, const ValveDynamics &dynamics, double to_current,
                                 const DynamicsParameters &parameters, unsigned int samples);
} // namespace servodrift::system
