#pragma once
// Physical constants and unit conversions. Everything inside servodrift is SI, except temperatures,
// which are in degC as in the empirical laws of model.md, and angles typed by users in degree.
#include <cmath>

namespace servodrift::units
{
  constexpr double pi = 3.14159265358979323846;
  /// Vacuum permeability as used by model.md (4 pi 1e-7 H/m; the 2019 SI value differs by 5e-10).
  constexpr double mu0 = 4.0e-7 * pi;
  constexpr double degree = pi / 180.0;        // rad per degree
  constexpr double celsius_to_kelvin = 273.15; // K at 0 degC
  constexpr double milli = 1e-3;
  constexpr double micro = 1e-6;
  constexpr double mega = 1e6;
} // namespace servodrift::units
