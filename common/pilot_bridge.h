#pragma once
// One half of the pilot-stage bridge (model.md E31 = E32, blocked spool, steady): the control
// pressure p at which the flow through the fixed orifice, Q_0(p_s - p), equals the flow through the
// nozzle-flapper gap, Q_N(p - p_r). Q_0 falls and Q_N rises with p, so the root in [p_r, p_s] is
// unique; a closed gap (Q_N = 0) gives p = p_s. Shared by the reduced-order flow stage and the
// system model, whatever computes the two flows.
#include <functional>

namespace servodrift
{
  double bridge_pressure(const std::function<double(double orifice_pressure_difference)> &orifice_flow,
                         const std::function<double(double nozzle_pressure_difference)> &nozzle_flow,
                         double supply_pressure, double return_pressure);
} // namespace servodrift
