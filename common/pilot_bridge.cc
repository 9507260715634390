#include "common/pilot_bridge.h"

#include "common/root_finding.h"

namespace servodrift
{
  double bridge_pressure(const std::function<double(double)> &net_inflow, double p_s, double p_r)
  {
    // to 1e-13 of the span (2 uPa for RV-1): the dynamic model starts from this point and must stay
    return find_root(net_inflow, p_r, p_s, net_inflow(p_r), net_inflow(p_s), 1e-13 * (p_s - p_r),
                     "pilot bridge pressure (E31 = E32)");
  }
} // namespace servodrift
