// The checks of the pilot stage that go beyond one entry's range (validate() in valve_validation.cc
// runs them in its order).
#include "common/error.h"
#include "common/parameters/pilot_stage.h"
#include "common/parameters/validation_helpers.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <string>

namespace servodrift
{
  using namespace validation;

  void PilotTimeAverageParameters::validate() const
  {
    if (!(steps_limit >= steps))
      refuse("Pilot stage/Time average/Steps limit", "= " + std::to_string(steps_limit) +
                                                       " must be at least `Pilot stage/Time average/Steps' = " +
                                                       std::to_string(steps));
  }

  void PilotStageParameters::validate() const
  {
    if (!(fixed_orifice_diameter > 0 && fixed_orifice_length > 0 && nozzle_diameter > 0))
      refuse("Pilot stage", "orifice and nozzle dimensions must be > 0");
    if (!(null_gap > 0))
      refuse("Pilot stage/Null gap", "= " + format_number(null_gap) + " m must be > 0");
    if (!(null_gap <= 0.25 * nozzle_diameter))
      refuse("Pilot stage/Null gap", "= " + format_number(null_gap) +
                                       " m must not exceed a quarter of the nozzle diameter, D_N/4 = " +
                                       format_number(0.25 * nozzle_diameter) +
                                       " m, or the nozzle bore instead of the curtain throttles (E32)");
    if (!(land_diameter > nozzle_diameter))
      refuse("Pilot stage/Land diameter", "= " + format_number(land_diameter) +
                                            " m must be above the nozzle diameter " +
                                            format_number(nozzle_diameter) + " m (E22)");
    if (!(reduced_order.nozzle_discharge_coefficient > 0))
      refuse("Pilot stage/Reduced order/Nozzle discharge coefficient", "must be > 0");
  }

  void PilotStageParameters::validate(const ValveDescription &v) const
  {
    // the null gap x0(T) stays open at every table temperature (2.3)
    const auto &op = v.operating;
    for (double T : v.sweeps.table_temperatures)
      {
        const auto g = laws::pilot_stage_geometry(*this, v.armature, v.expansion, T, op.reference_temperature);
        if (!(g.null_gap > 0))
          refuse("Pilot stage/Nozzle seat span", "makes the null gap close at " + format_number(T) + " degC (2.3)");
      }
  }

  void PilotStageParameters::validate_dynamic_model(const ValveDescription &v) const
  {
    const auto &sp = v.spool;
    const double swept = 0.25 * units::pi * sp.control_diameter * sp.control_diameter * sp.stroke_limit;
    if (!(control_cavity_volume > swept))
      refuse("Pilot stage/Control cavity volume",
             "= " + format_number(control_cavity_volume) + " m^3 must exceed the volume the spool end sweeps over "
               "its stroke, A_v x stroke = " + format_number(swept) + " m^3 (E33: V_0 -+ A_v x_v > 0)");
  }
} // namespace servodrift
