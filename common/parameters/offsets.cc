#include "common/parameters/offsets.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void OffsetParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Spring tube rest angle", "0", Patterns::Double(-10, 10),
                      "Rest angle theta_s of the unloaded spring tube (E29, E39). [deg]");
    prm.declare_entry("Magnetic null", "0", Patterns::Double(-10, 10),
                      "Armature angle theta_m at which the torque motor gives no torque at zero "
                      "current (E29, E39). [deg]");
    prm.declare_entry("Hydraulic null", "0", Patterns::Double(-1e-3, 1e-3),
                      "Flapper position x_n, at theta = 0, of the hydraulic null (equal gaps); the "
                      "left gap is x0 - (r theta - x_n) (E29, E39). [m]");
    prm.declare_entry("Deviation target", "magnetic-null",
                      Patterns::Selection("magnetic-null|spring-tube-rest-angle|hydraulic-null"),
                      "Which offset of E39 the assembly deviation angle theta_d of the drift map drives "
                      "(D8): theta_m += theta_d, theta_s -= theta_d (the literal reading E38), or "
                      "x_n -= r theta_d. [-]");
    prm.declare_entry("Nulling", "nulled-at-reference",
                      Patterns::Selection("nulled-at-reference|as-assembled"),
                      "Drift convention (D8, D9): nulled-at-reference re-nulls each valve at T0 with "
                      "its hydraulic null x_n and measures deviations from the same valve at T0; "
                      "as-assembled keeps the offsets and measures deviations from theta_d = 0 at the "
                      "same temperature (the paper's). [-]");
    prm.leave_subsection();
  }
} // namespace servodrift
