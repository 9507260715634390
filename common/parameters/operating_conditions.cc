#include "common/parameters/operating_conditions.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void OperatingConditions::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Supply pressure", "21e6", Patterns::Double(0, 1e9),
                      "Supply pressure p_s at the fixed orifices, gauge (E31). [Pa]");
    prm.declare_entry("Return pressure", "0.4e6", Patterns::Double(0, 1e9),
                      "Return (nozzle-chamber) pressure p_r, gauge (E32); must be below the supply "
                      "pressure. [Pa]");
    prm.declare_entry("Reference temperature", "40", Patterns::Double(-273.15, 1000),
                      "Reference temperature T0: dimensions of the torque motor and the pilot stage, "
                      "the magnet remanence and the oil density are given at T0, and a valve 'nulled at "
                      "reference' is nulled at T0 (D3). [degC]");
    prm.declare_entry("Rated current", "0.020", Patterns::Double(0, 10),
                      "Rated differential coil current (D7); the output-pressure drift is evaluated at "
                      "this current (D9). [A]");
    prm.declare_entry("Ambient pressure", "101325", Patterns::Double(0, 1e7),
                      "Absolute pressure of gauge zero: the supply and return pressures are gauge, and "
                      "the field-level flow cases compare their lowest absolute pressure with the "
                      "vapour pressure (C12). [Pa]");
    prm.leave_subsection();
  }
} // namespace servodrift
