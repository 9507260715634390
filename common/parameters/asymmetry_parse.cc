#include "common/parameters/asymmetry.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void AsymmetryParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    for (const bool left : {true, false})
      {
        const std::string side = side_name(left);
        SideDeviations &d = left ? this->left : right;
        d.orifice_diameter = prm.get_double(side + " orifice diameter deviation");
        d.nozzle_diameter = prm.get_double(side + " nozzle diameter deviation");
        d.null_gap = prm.get_double(side + " null gap deviation");
        d.orifice_discharge_factor = prm.get_double(side + " orifice discharge factor");
        d.nozzle_discharge_factor = prm.get_double(side + " nozzle discharge factor");
      }
    lower_gap_mismatch = prm.get_double("Lower gap mismatch");
    left_remanence = prm.get_double("Left magnet remanence deviation");
    right_remanence = prm.get_double("Right magnet remanence deviation");
    prm.leave_subsection();
  }
} // namespace servodrift
