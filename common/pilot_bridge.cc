#include "common/pilot_bridge.h"

#include "common/root_finding.h"

namespace servodrift
{
  double bridge_pressure(const std::function<double(double)> &orifice_flow,
                         const std::function<double(double)> &nozzle_flow, double p_s, double p_r)
  {
    // E31 - E32: continuity of the control cavity
    const auto imbalance = [&](double p) { return orifice_flow(p_s - p) - nozzle_flow(p - p_r); };
    const double f_low = imbalance(p_r), f_high = imbalance(p_s);
    return find_root(imbalance, p_r, p_s, f_low, f_high, 1e-10 * (p_s - p_r), "pilot bridge pressure (E31 = E32)");
  }
} // namespace servodrift
