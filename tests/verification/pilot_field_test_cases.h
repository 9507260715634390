#pragma once
// RV-1's pilot-stage field cases that several verification files solve: the nozzle at its null
// conditions and the laminar fixed orifice, each from rest.
#include "flow/pilot/pilot_field.h"

namespace servodrift::flow::test_cases
{
  /// RV-1's nozzle at its null conditions (40 degC, dp = p_c - p_r = 10.4 MPa, cavitation on),
  /// solved from rest at `resolution' and gap h; returns the result
  inline PilotFieldResult nozzle_at_null(const ValveDescription &v, double h, double resolution = 1)
  {
    PilotFieldCase c = pilot_field_case(v, 40);
    c.resolution = resolution;
    PilotField nozzle(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, h);
    return nozzle.solve(10.4e6);
  }

  inline PilotFieldResult orifice_laminar(const ValveDescription &v, double resolution = 1)
  {
    PilotFieldCase c = pilot_field_case(v, 40);
    c.resolution = resolution;
    PilotField orifice(pilot_field_settings(v), PilotGeometry::fixed_orifice, c);
    return orifice.solve(400e3); // Re_0 = 493, laminar
  }
} // namespace servodrift::flow::test_cases
