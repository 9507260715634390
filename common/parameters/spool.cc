#include "common/parameters/spool.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void SpoolParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Control diameter", "5.0e-3", Patterns::Double(0, 1),
                      "Spool end diameter d_v; the control pressures act on A_v = pi d_v^2/4 (E34, "
                      "E35). [m]");
    prm.declare_entry("Feedback diameter", "4.0e-3", Patterns::Double(0, 1),
                      "Feedback plunger diameter d_fb; the brake pressure acts on A_fb = pi d_fb^2/4 "
                      "against the control force (E35). [m]");
    prm.declare_entry("Mass", "4.0e-3", Patterns::Double(0, 10), "Spool mass m_v (E35; dynamics). [kg]");
    prm.declare_entry("Spring rate", "1.0e3", Patterns::Double(0, 1e8),
                      "Return-spring rate k_s (E35, C5). [N/m]");
    prm.declare_entry("Spring preload", "0.33", Patterns::Double(-1e4, 1e4),
                      "Return-spring preload F_s0, pushing towards negative x_v (E35, C5). [N]");
    prm.declare_entry("Area gradient", "15.708e-3", Patterns::Double(0, 1),
                      "Metering area gradient W, pi d_v for a full annulus (E36). [m]");
    prm.declare_entry("Overlap", "20e-6", Patterns::Double(0, 1e-2),
                      "Overlap x_ov of each metering land, positive = overlapped; must be positive for "
                      "a unique blocked-port steady state (E36). [m]");
    prm.declare_entry("Stroke limit", "0.4e-3", Patterns::Double(0, 0.1),
                      "Spool travel limit: |x_v| <= stroke limit; beyond it the spool is on its stop. "
                      "[m]");
    prm.declare_entry("Stop stiffness", "1e8", Patterns::Double(1e3, 1e13),
                      "Stiffness of the stops at the stroke limits: a spool driven past a limit sinks "
                      "in by force/stiffness (static and dynamic model alike). [N/m]");
    prm.declare_entry("Stop damping ratio", "0.7", Patterns::Double(0, 10),
                      "Damping ratio of the stops, c = 2 zeta sqrt(stiffness m_v), active only in "
                      "contact and never pulling (dynamics). [1]");
    prm.declare_entry("Discharge coefficient", "0.61", Patterns::Double(0, 1),
                      "Discharge coefficient C_dv of the metering edges (E35, E36). [1]");
    prm.declare_entry("Jet angle", "69", Patterns::Double(0, 90),
                      "Jet angle of the steady flow force (E35). [deg]");
    prm.declare_entry("Radial clearance", "3e-6", Patterns::Double(0, 1e-3),
                      "Radial clearance c_r between spool and sleeve: lap leakage pi d_v c_r^3 dp/(12 mu "
                      "L) (E36) and the viscous damping B_v (2.7, C14). [m]");
    prm.declare_entry("Land length", "12e-3", Patterns::Double(0, 1),
                      "Length L of the spool's sealing lands; viscous damping B_v = mu(T) pi d_v L/c_r, "
                      "0.748 N*s/m at 40 degC for RV-1 (2.7, C14; dynamics). [m]");
    prm.declare_entry("Minimum leak length", "1e-6", Patterns::Double(1e-7, 1e-2),
                      "Floor of the leak length x_ov -+ x_v of the lap leakage (E36, C14), so that the "
                      "leakage stays finite at and beyond the lap edge, where the metering orifice takes "
                      "over. At least 0.1 um: far below the radial clearance, where the laminar leakage "
                      "law no longer holds anyway, the lap edge's leakage turns so sharp that the "
                      "dynamics' time steps shrink with it (1e-8 m: over 1e6 steps per response). [m]");
    prm.declare_entry("Laminar transition number", "1000", Patterns::Double(1, 1e6),
                      "lambda_c of the metering edges' tanh blend C_d = C_dv tanh(2 lambda/lambda_c), "
                      "lambda = D_h sqrt(2 dp/rho)/nu with the hydraulic diameter D_h = 2 x the opening "
                      "of the annular slot (E20, C14). [1]");
    prm.declare_entry("Brake volume", "2e-5", Patterns::Double(0, 1),
                      "Volume V_B of brake port, line and brake (E37; dynamics). [m^3]");
    prm.declare_entry("Brake port", "brake-volume", Patterns::Selection("brake-volume|blocked-port"),
                      "What the brake port feeds in the dynamics (E37, no load flow in either case): "
                      "brake-volume, the brake and its line (`Brake volume'), or blocked-port, the port "
                      "capped at the valve (`Port volume'), as on a test bench. [-]");
    prm.declare_entry("Port volume", "1e-6", Patterns::Double(0, 1),
                      "Volume of the valve's own brake-port passage, used when `Brake port' = "
                      "blocked-port (E37; dynamics). [m^3]");
    prm.leave_subsection();
  }
} // namespace servodrift
