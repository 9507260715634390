#pragma once
// The check that the dynamic model and the static solver describe one valve (issue 23): integrated
// from the static operating point under the same constant command, the valve stays there; integrated
// from rest (supply switched on with every pressure at return, armature and spool centred), it
// settles on the static operating point.
#include "common/parameters/dynamics.h"
#include "system/valve_dynamics.h"
#include "system/valve_model.h"

namespace servodrift::system
{
  /// The state of the valve at rest before its supply is switched on: p_L = p_R = p_B = p_r, theta,
  /// x_v, the rates and the coil current zero.
  ValveState rest_state(const ValveEquations &equations);

  struct SteadyStateCheck
  {
    double drift_from_static = 0;    ///< largest scaled distance from the static point while integrating from it [1]
    double distance_from_rest = 0;   ///< scaled distance of the settled start-up from the static point [1]
    double settling_from_rest = 0;   ///< simulated time until the start-up changed by < 1e-10 per chunk [s]
    double duration = 0;             ///< simulated time from the static point [s]
  };

  /// Both integrations at the command current `command'.
  SteadyStateCheck steady_state_check(const ValveModel &model, const ValveDynamics &dynamics, double command,
                                      const DynamicsParameters &parameters);
} // namespace servodrift::system
