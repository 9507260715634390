#include "common/paper_fits.h"

#include "common/grid_function.h"

#include <algorithm>

namespace servodrift::paper
{
  namespace
  {
    ClampedValue clamp(double x, double lo, double hi)
    {
      return {std::clamp(x, lo, hi), x < lo || x > hi};
    }
  } // namespace

  ClampedValue fixed_orifice_discharge_coefficient(double Re)
  {
    // C6: the window of E26 is Re_0 in [0.1, 1.2] x 9.74e3
    const ClampedValue r = clamp(Re, 0.1 * 9.74e3, 1.2 * 9.74e3);
    const double x = r.value;
    return {((4.196e-13 * x - 1.226e-8) * x + 1.202e-4) * x + 0.3875, r.clamped}; // E26
  }

  ClampedValue nozzle_discharge_coefficient(double T)
  {
    const ClampedValue t = clamp(T, 40.0, 120.0);
    return {0.5841 + 3.49e-4 * t.value - 2.26e-6 * t.value * t.value, t.clamped}; // E27, T-part
  }

  ClampedValue flow_force_stiffness(double T)
  {
    // model.md section 3 item 10, paper-fidelity table [kN/m]
    static const GridFunction table("paper K_f(T) table", {"temperature[degC]"},
                                    {{40, 50, 60, 70, 80, 90, 100, 110, 120}},
                                    {57.5e3, 29.5e3, 15.2e3, 21.0e3, 25.5e3, 28.9e3, 31.4e3, 33.2e3, 34.5e3});
    const ClampedValue t = clamp(T, 40.0, 120.0);
    return {table(t.value), t.clamped};
  }
} // namespace servodrift::paper
