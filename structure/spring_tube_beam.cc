#include "structure/spring_tube_beam.h"

#include "common/thermal_laws.h"
#include "common/units.h"

#include <cmath>

namespace servodrift::structure
{
  BeamTube beam_tube(const ValveDescription &valve, double T)
  {
    const auto geometry = laws::spring_tube_geometry(valve.spring_tube, valve.expansion, T); // E13
    BeamTube b;
    b.youngs_modulus = laws::youngs_modulus(valve.spring_tube, T); // E12
    const double D = geometry.outer_diameter, d = geometry.inner_diameter;
    b.second_moment = units::pi * (std::pow(D, 4) - std::pow(d, 4)) / 64.0; // E11
    b.length = geometry.length;
    b.outer_radius = D / 2;
    b.rotational_stiffness = b.youngs_modulus * b.second_moment / b.length; // E11: K_a = E I/l
    return b;
  }

  double BeamTube::tip_rotation(double M, double V) const
  {
    return (M * length + V * length * length / 2) / (youngs_modulus * second_moment);
  }

  double BeamTube::tip_deflection(double M, double V) const
  {
    return (M * length * length / 2 + V * length * length * length / 3) / (youngs_modulus * second_moment);
  }
} // namespace servodrift::structure
