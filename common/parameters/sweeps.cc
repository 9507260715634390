#include "common/parameters/sweeps.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void SweepParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Table temperatures", "-55, -45, -35, -20, 0, 20, 40, 60, 80, 100, 120, 135",
                      double_list(-273.15, 1000, 1),
                      "Temperatures at which every stage writes its coefficient table (D3); strictly "
                      "increasing, inside the fluid's viscosity-law window. The default spans an aircraft "
                      "valve's range, -55 to 135 degC, closer at the cold end, where the viscosity changes "
                      "fastest (doc/validation.md, \"The whole temperature range\"). [degC]");
    prm.declare_entry("Motor angles",
                      "-0.25, -0.15, -0.1, -0.05, 0, 0.05, 0.1, 0.15, 0.25",
                      double_list(-10, 10, 2),
                      "Armature angles of the torque_motor table, strictly increasing; they must cover "
                      "the armature angles of the drift map's operating points (a query beyond them "
                      "stops the system model, naming this entry), include +-0.1 deg for the secant "
                      "K_m (C1) and, for the dynamics, reach the nozzle contacts (+-0.23 deg for RV-1). "
                      "[deg]");
    prm.declare_entry("Motor currents",
                      "-0.03, -0.02, -0.01, 0, 0.01, 0.02, 0.03",
                      double_list(-10, 10, 2),
                      "Differential coil currents of the torque_motor table, strictly increasing; must "
                      "include 0 and the rated current, and cover the dynamics' inputs (bias -+ the "
                      "largest sine amplitude: -10..30 mA for RV-1). [A]");
    prm.declare_entry("Pressure fractions",
                      "0, 0.0025, 0.01, 0.025, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1",
                      double_list(0, 1, 2),
                      "Pressure differences of the fixed_orifice and nozzle_flapper tables as "
                      "fractions of p_s - p_r, strictly increasing; 0 to 1 covers every bridge state. "
                      "[1]");
    prm.declare_entry("Gap fractions",
                      "0, 0.05, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1, 1.125, 1.25, 1.375, "
                      "1.5, 1.625, 1.75, 1.875, 2, 2.2",
                      double_list(0, 10, 2),
                      "Nozzle-flapper gaps of the nozzle_flapper table as fractions of the null gap x0 "
                      "at T0, strictly increasing; 0 to 2 x0(T)/x0 covers the flapper's travel "
                      "between the nozzles. [1]");
    prm.declare_entry("Field orifice pressure fractions", "0.05, 0.25, 0.5, 0.75, 1", double_list(0, 1, 1),
                      "Field level: pressure differences of the fixed_orifice table's computed rows as "
                      "fractions of p_s - p_r, strictly increasing (the table adds dp = 0, where Q = 0). "
                      "[1]");
    prm.declare_entry("Field gap fractions", "0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75", double_list(0, 10, 1),
                      "Field level: nozzle-flapper gaps of the nozzle_flapper table's computed rows as "
                      "fractions of x0 at T0, strictly increasing and > 0 (the table adds the closed "
                      "gap). The default is x0 -+ x_f for x_f = 0, 10, 20, 30 um (issue 5); the drift "
                      "map's flapper travel must stay inside. [1]");
    prm.declare_entry("Field nozzle pressure fractions", "0.15, 0.5, 1", double_list(0, 1, 1),
                      "Field level: nozzle pressure differences p_c - p_r of the nozzle_flapper table's "
                      "computed rows as fractions of p_s - p_r, strictly increasing (the table adds dp = "
                      "0); the bridge needs up to 1. [1]");
    prm.declare_entry("Drift temperatures",
                      "-55, -50, -45, -40, -35, -30, -25, -20, -15, -10, -5, 0, 5, 10, 15, 20, 25, 30, 35, 40, "
                      "45, 50, 55, 60, 65, 70, 75, 80, 85, 90, 95, 100, 105, 110, 115, 120, 125, 130, 135",
                      double_list(-273.15, 1000, 2),
                      "Temperatures of the drift map (D9), strictly increasing, within the table "
                      "temperatures. [degC]");
    prm.declare_entry("Deviation angles",
                      "-0.05, -0.045, -0.04, -0.035, -0.03, -0.025, -0.02, -0.015, -0.01, -0.005, 0, "
                      "0.005, 0.01, 0.015, 0.02, 0.025, 0.03, 0.035, 0.04, 0.045, 0.05",
                      double_list(-10, 10, 1),
                      "Assembly deviation angles theta_d of the drift map (D8), strictly increasing. "
                      "[deg]");
    prm.leave_subsection();
  }
} // namespace servodrift
