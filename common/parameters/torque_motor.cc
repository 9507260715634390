#include "common/parameters/torque_motor.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void TorqueMotorParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Model level", "field", Patterns::Selection("reduced-order|field"),
                      "Which model computes the torque_motor table (D13): field, the planar FEM of "
                      "D10 (magnetics/, meshes/torque_motor.geo); reduced-order, the four-mesh magnetic "
                      "circuit E3 with E6-E10. [-]");
    prm.declare_entry("Turns per coil", "1100", Patterns::Integer(1, 1000000),
                      "Turns N_c of each of the two coils, one per armature arm (2.1). [1]");
    prm.declare_entry("Coil connection", "push-pull", Patterns::Selection("push-pull|series-aiding"),
                      "push-pull: net control MMF N_c*i for the differential current i (D7, Merritt); "
                      "series-aiding: 2*N_c*i (doubles K_t). [-]");
    prm.declare_entry("Pivot to pole-face distance", "14.8e-3", Patterns::Double(0, 1),
                      "Distance a from the armature pivot to the centre of each pole face (E2). [m]");
    prm.declare_entry("Pole face width", "4.0e-3", Patterns::Double(0, 1),
                      "Pole-face width w_p (across the armature); A_g = w_p*l_p (E2). [m]");
    prm.declare_entry("Pole face length", "4.0e-3", Patterns::Double(0, 1),
                      "Pole-face length l_p (along the armature) (E2). [m]");
    prm.declare_entry("Gap fringing", "none", Patterns::Selection("none|expanded-area"),
                      "none: gap area w_p*l_p; expanded-area: (w_p + g)(l_p + g), a simple fringing "
                      "correction (E2). [-]");
    prm.declare_entry("Armature thickness", "3.0e-3", Patterns::Double(0, 1),
                      "Armature thickness H_ar across the gaps (E6, E7). [m]");
    prm.declare_entry("Armature width", "4.0e-3", Patterns::Double(0, 1),
                      "Armature width, out of the plane of the planar field model (2.2). [m]");
    prm.declare_entry("Armature length", "33.6e-3", Patterns::Double(0, 1),
                      "Armature length, tip to tip (2.2). [m]");
    prm.declare_entry("Armature height", "10.8e-3", Patterns::Double(0, 1),
                      "Height H_a of the armature centre above the datum, set by the spring tube "
                      "(E6, E7). [m]");
    prm.declare_entry("Lower pole height", "9.0e-3", Patterns::Double(0, 1),
                      "Height H_c of the lower pole face above the datum (E6). [m]");
    prm.declare_entry("Upper pole thickness", "3.0e-3", Patterns::Double(0, 1),
                      "Thickness H_c' of the upper pole plate (E7). [m]");
    prm.declare_entry("Upper pole tip protrusion", "2.4e-3", Patterns::Double(0, 1),
                      "Downward protrusion h_p of the upper pole tip below the magnet seat (E7). [m]");
    prm.declare_entry("Magnet length", "12.0e-3", Patterns::Double(0, 1),
                      "Magnet length l_m along its magnetisation, which is also its height H_m in the "
                      "stack-up (E7, E8). [m]");
    prm.declare_entry("Magnet width", "5.0e-3", Patterns::Double(0, 1),
                      "Magnet cross-section width; A_m = width*depth per magnet (E2). [m]");
    prm.declare_entry("Magnet depth", "5.0e-3", Patterns::Double(0, 1),
                      "Magnet cross-section depth (E2). [m]");
    prm.declare_entry("Number of magnets", "2", Patterns::Integer(1, 16),
                      "Magnets in parallel between the pole plates (E2: A_m,tot = n*A_m). [1]");
    prm.declare_entry("Remanence", "0.90", Patterns::Double(0, 2.5),
                      "Magnet remanence B_r0 at the reference temperature; LNGT60 / AlNiCo 8 (D4). [T]");
    prm.declare_entry("Remanence temperature coefficient", "-2.5e-4", Patterns::Double(-0.1, 0.1),
                      "Reversible temperature coefficient alpha_Br of the remanence (E8, D4). [1/degC]");
    prm.declare_entry("Irreversible loss", "0", Patterns::Double(0, 1),
                      "Irreversible remanence loss R_irr of the magnet (E8). [1]");
    prm.declare_entry("Recoil permeability", "6.51", Patterns::Double(1, 1e4),
                      "Relative permeability mu_rm of the linear recoil line, so that H_cB = "
                      "B_r/(mu0*mu_rm) = 110 kA/m (E8, D4). [1]");
    prm.declare_entry("Leakage reluctance", "1.42e7", Patterns::Double(0, 1e12),
                      "Leakage reluctance R_l between the pole plates (E3), temperature-independent as "
                      "in model.md 1.3. [A/Wb]");
    prm.declare_entry("Pole piece reluctance", "0", Patterns::Double(0, 1e12),
                      "Pole-piece (magnetic conductor) reluctance R_c in series with the magnets (E3). "
                      "[A/Wb]");
    prm.declare_entry("Armature reluctance", "0", Patterns::Double(0, 1e12),
                      "Armature reluctance R_a between its two ends (E3). [A/Wb]");
    prm.declare_entry("Saturation polarisation", "1.50", Patterns::Double(0, 3),
                      "Saturation polarisation J_s of the 1J50 arctan B-H law "
                      "B = mu0 H + (2 J_s/pi) atan(pi chi0 mu0 H/(2 J_s)) (2.2); field level. [T]");
    prm.declare_entry("Initial susceptibility", "2e4", Patterns::Double(0, 1e7),
                      "Initial susceptibility chi0 of the 1J50 arctan B-H law (2.2); field level. [1]");
    prm.declare_entry("Model depth", "4.0e-3", Patterns::Double(0, 1),
                      "Out-of-plane depth w_d of the planar field model (D10, 4.1). [m]");
    prm.declare_entry("Magnetic spring law", "circuit", Patterns::Selection("circuit|paper-fit"),
                      "circuit: the torque as computed; paper-fit: its secant magnetic spring (C1) "
                      "replaced by the paper's fit E25, K_m = 11.61 - 0.004837 T N*m/rad, clamped to "
                      "40..120 degC and flagged outside that window (C6; paper preset D2). [-]");
    prm.declare_entry("Field element degree", "1", Patterns::Integer(1, 2),
                      "Degree of the FE_Q elements of A_z in the field model. [1]");
    prm.declare_entry("Field mesh resolution", "1", Patterns::Double(0.1, 16),
                      "Scales the field model's mesh: element sizes / resolution, gap layers x "
                      "resolution. [1]");
    prm.declare_entry("Field gap layers", "8", Patterns::Integer(2, 200),
                      "Element layers across each working gap at resolution 1 (at least 8, issue 3). [1]");
    prm.declare_entry("Field magnet width", "4.852e-3", Patterns::Double(0, 0.1),
                      "In-plane width of each equivalent magnet block at T0 (D10): RV-1's value is "
                      "calibrated (C10, `servodrift magnetics --calibrate') so that the field model's mean "
                      "working-gap flux density at null equals the circuit's (doc/method.md); "
                      "uncalibrated, A_m/w_d = 6.25 mm (4.1). [m]");
    prm.declare_entry("Field magnet clearance", "2.2e-3", Patterns::Double(0, 0.1),
                      "Distance from the outer edge of the pole tips to the magnet blocks (field model). "
                      "[m]");
    prm.declare_entry("Upper plate thickness", "3.0e-3", Patterns::Double(0, 0.1),
                      "Thickness of the upper pole plate above the magnet seat (field model). [m]");
    prm.declare_entry("Coil inner position", "3.0e-3", Patterns::Double(0, 0.1),
                      "Coil window of the field model: from this distance from the pivot ... [m]");
    prm.declare_entry("Coil outer position", "11.0e-3", Patterns::Double(0, 0.1),
                      "... to this one, short of the pole tips (field model). [m]");
    prm.declare_entry("Coil height", "2.0e-3", Patterns::Double(0, 0.1),
                      "Height of each of the coil's two current regions above and below the arm; "
                      "J = (net MMF/2)/(window area) per arm (field model). [m]");
    prm.declare_entry("Coil clearance", "0.2e-3", Patterns::Double(0, 0.1),
                      "Gap between the armature and the coil regions (field model). [m]");
    prm.declare_entry("Air boundary radius", "0.3", Patterns::Double(0, 10),
                      "Radius of the air domain around the pivot; A_z = 0 on it (field model). [m]");
    prm.declare_entry("Newton tolerance", "1e-10", Patterns::Double(1e-15, 1e-2),
                      "Newton stops when the residual has fallen by this factor from its value at "
                      "A_z = 0 (field model). [1]");
    prm.declare_entry("Coil resistance", "140", Patterns::Double(0, 1e6),
                      "Resistance of each coil at 20 degC, 80..200 Ohm for RV-1 (2.1); voltage drive "
                      "L_c di/dt = u - R_c(T) i (1.20; dynamics). [Ohm]");
    prm.declare_entry("Coil resistance temperature coefficient", "3.93e-3", Patterns::Double(0, 0.1),
                      "alpha_Cu of the copper coils, R_c(T) = R_c (1 + alpha_Cu (T - 20)) (2.1; dynamics). "
                      "[1/degC]");
    prm.declare_entry("Coil inductance", "0.041", Patterns::Double(0, 100),
                      "Inductance of each coil, N_c^2/(2 R_g) = 0.041 H for RV-1 (2.1); voltage drive "
                      "(dynamics). [H]");
    prm.declare_entry("Coil drive", "current", Patterns::Selection("current|voltage"),
                      "current: the amplifier imposes the control current i (default); voltage: it "
                      "imposes u = R_c(T0) i_command and the coil current is a state, L di/dt = u - R(T) "
                      "i - (dT_em/di) dtheta/dt, with one coil's R and L for push-pull and 2 R, 4 L for "
                      "series-aiding (1.20; dynamics). [-]");
    prm.leave_subsection();
  }
} // namespace servodrift
