#pragma once
// The closed-form checks of the dynamic model (issue 23, model.md 2.5, C13), at one temperature:
// the armature mode of the subsystem that model.md's 1 kHz belongs to (spool blocked, control
// pressures following the flapper at once) against sqrt((K_a - K_m + r^2 K_f)/J_a), the same
// armature with compressible cavities and in the coupled valve, and the control-cavity pressure time
// constant against V_0/(beta_e dQ/dp). All at the null (i = 0, flapper centred), where model.md's
// figures hold, except the coupled mode at the bias.
#include "system/linear_analysis.h"
#include "system/valve_dynamics.h"
#include "system/valve_model.h"

namespace servodrift::system
{
  struct DynamicChecks
  {
    /// sqrt((K_a - K_m + r^2 K_f)/J_a)/(2 pi), K_m the slope at null, K_f the blocked bridge's [Hz]
    double armature_closed_form = 0;
    /// the linearisation with the spool held and p_L, p_R eliminated quasi-statically [Hz]
    double armature_blocked = 0;
    /// the spool held, the cavities compressible (V_0, beta_e): the undamped |lambda| [Hz]
    double armature_compressible = 0;
    /// the coupled valve at the null: the mode with the largest armature participation [Hz]
    double armature_coupled = 0;
    /// V/(beta_e (Q_0/(2 dp_0) + Q_N/(2 dp_N))): turbulent orifices (Q ~ sqrt(dp)) at null, with the
    /// cavity's volume V = V_0 + A_v x_v where the spool sits [s]
    double pressure_time_constant_closed_form = 0;
    /// V/(beta_e (dQ_0/dp + dQ_N/dp)) with the tables' own derivatives [s]
    double pressure_time_constant_tables = 0;
    /// -1/lambda of p_L with the flapper and the spool held, from the linearisation [s]
    double pressure_time_constant = 0;
  };

  DynamicChecks dynamic_checks(const ValveModel &model, const ValveDynamics &dynamics);
} // namespace servodrift::system
