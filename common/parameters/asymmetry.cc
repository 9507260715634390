#include "common/parameters/asymmetry.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void AsymmetryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    for (const bool left : {true, false})
      {
        const std::string side = side_name(left), p = left ? "p_L" : "p_R";
        prm.declare_entry(side + " orifice diameter deviation", "0", Patterns::Double(-1e-4, 1e-4),
                          "Diameter of the " + std::string(left ? "left" : "right") +
                            " fixed orifice (feeding " + p + ") minus the nominal `Pilot stage/Fixed orifice diameter' "
                            "(E31). The tables hold the nominal bore: the side's flow is the table's times the "
                            "ratio of the bore tables (`Pilot stage/Bore sensitivity/Tables') or of E21 "
                            "(doc/method.md, \"A bore off the tables' geometry\"). [m]");
        prm.declare_entry(side + " nozzle diameter deviation", "0", Patterns::Double(-1e-4, 1e-4),
                          "Diameter of the " + std::string(left ? "left" : "right") +
                            " nozzle minus the nominal `Pilot stage/Nozzle diameter' (E32, E23): the side's flow "
                            "and jet force are the table's times the ratios of the bore tables or of E22 and "
                            "E23 (doc/method.md, \"A bore off the tables' geometry\"). [m]");
        prm.declare_entry(side + " null gap deviation", "0", Patterns::Double(-5e-5, 5e-5),
                          "This side's nozzle-flapper gap at x_f = 0 minus the nominal x0(T) (flapper "
                          "centring, nozzle position). [m]");
        prm.declare_entry(side + " orifice discharge factor", "1", Patterns::Double(0.5, 1.5),
                          "Discharge coefficient of this side's fixed orifice over the table's (edge "
                          "quality): multiplies its flow (E31). [1]");
        prm.declare_entry(side + " nozzle discharge factor", "1", Patterns::Double(0.5, 1.5),
                          "Discharge coefficient of this side's nozzle-flapper gap over the table's "
                          "(edge quality): multiplies its flow (E32). [1]");
      }
    prm.declare_entry("Lower gap mismatch", "0", Patterns::Double(-5e-5, 5e-5),
                      "Torque motor: g_1 - g_2 at theta = 0, the lower pole piece's faces ground to "
                      "different heights (E2, E3); mapped to a magnetic null and K_m, K_t at each "
                      "temperature through the circuit E3. [m]");
    prm.declare_entry("Left magnet remanence deviation", "0", Patterns::Double(-0.2, 0.2),
                      "(B_r - nominal B_r)/nominal B_r of the left magnet (E8); E3 has the magnets in "
                      "parallel, so K_m and K_t follow the mean of the two. [1]");
    prm.declare_entry("Right magnet remanence deviation", "0", Patterns::Double(-0.2, 0.2),
                      "(B_r - nominal B_r)/nominal B_r of the right magnet (E8). [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
