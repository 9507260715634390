#pragma once
// One half of the pilot-stage bridge at rest (model.md E33 with no spool motion, i.e. E31 = E32,
// blocked spool, steady): the control pressure p at which the net inflow of the control cavity,
// Q_0(p_s - p) - Q_N(p - p_r), vanishes. Q_0 falls and Q_N rises with p, so the root in [p_r, p_s]
// is unique; a closed gap (Q_N = 0) gives p = p_s. Shared by the reduced-order flow stage and the
// system model, whatever computes the two flows.
#include <functional>

namespace servodrift
{
  double bridge_pressure(const std::function<double(double control_pressure)> &net_inflow, double supply_pressure,
                         double return_pressure);
} // namespace servodrift
