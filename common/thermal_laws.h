#pragma once
// Every temperature-dependent law of the valve in one place (model.md E6-E8, E12-E16, 2.3, 2.8).
// Each law is a small function of the temperature T in degC; the field solvers and the
// reduced-order models call these, never their own copy.
#include "common/parameters/fluid.h"
#include "common/parameters/pilot_stage.h"
#include "common/parameters/spool.h"
#include "common/parameters/spring_tube.h"
#include "common/parameters/thermal_expansion.h"
#include "common/parameters/torque_motor.h"
#include "common/parameters/armature.h"

#include <string>
#include <vector>

namespace servodrift::laws
{
  /// Linear thermal expansion of one dimension: L(T) = L_ref (1 + alpha (T - T_ref)) (E6, E7, E13).
  inline double expanded(double length_at_reference, double alpha, double T, double T_reference)
  {
    return length_at_reference * (1.0 + alpha * (T - T_reference));
  }

  struct ValueAndSlope
  {
    double value; ///< the property
    double slope; ///< its derivative with respect to T [unit/degC]
  };

  /// The hydraulic oil (E14-E16, 2.8, D6). Every evaluation checks the law's temperature window.
  class Oil
  {
  public:
    Oil(const FluidParameters &fluid, double reference_temperature);

    /// nu(T): Vogel A exp(B/(T + C)) (E16) or nu0 exp(-alpha_nu (T - T0)) (E14) [m^2/s].
    ValueAndSlope kinematic_viscosity(double T) const;
    /// rho(T) = rho0 (1 - alpha_rho (T - T0)) (E15; pressure term dropped as in [K22]) [kg/m^3].
    ValueAndSlope density(double T) const;
    /// mu = rho nu [Pa*s].
    double dynamic_viscosity(double T) const;
    /// beta_e(T) = beta_e0 (1 - c (T - T0)) (2.8) [Pa].
    double effective_bulk_modulus(double T) const;
    /// Throws InputError if T is outside the viscosity law's window; `what' names the quantity.
    void check_temperature(double T, const char *what = "temperature") const;

  private:
    FluidParameters fluid;
    double T0;
  };

  /// E(T) = E_ref (1 - eta (T - T_ref)) (E12) [Pa].
  double youngs_modulus(const SpringTubeParameters &tube, double T);

  /// Spring-tube dimensions at T, all growing with alpha_s from the tube's reference temperature
  /// (E13, C3).
  struct SpringTubeGeometry
  {
    double outer_diameter; ///< D(T) [m]
    double inner_diameter; ///< d(T) [m]
    double length;         ///< l(T) [m]
    double base_flange_diameter; ///< [m]
    double base_flange_height;   ///< 0: no flange [m]
    double top_collar_diameter;  ///< [m]
    double top_collar_height;    ///< 0: no collar [m]
  };
  SpringTubeGeometry spring_tube_geometry(const SpringTubeParameters &tube, const ThermalExpansion &alpha,
                                          double T);

  /// Torque-motor dimensions at T (E6, E7 and the growth of a, A_g, l_m, A_m; model.md 1.3).
  struct TorqueMotorGeometry
  {
    double pivot_to_pole_distance; ///< a(T), armature [m]
    double pole_face_width;        ///< w_p(T), pole pieces [m]
    double pole_face_length;       ///< l_p(T), pole pieces [m]
    double lower_gap;              ///< g_12(T) (E6) [m]
    double upper_gap;              ///< g_34(T) (E7) [m]
    double armature_thickness;     ///< H_ar(T) [m]
    double magnet_length;          ///< l_m(T) [m]
    double magnet_area;            ///< A_m(T) of one magnet [m^2]
  };
  TorqueMotorGeometry torque_motor_geometry(const TorqueMotorParameters &motor,
                                            const ThermalExpansion &alpha, double T, double T0);

  /// B_r(T) = B_r0 [1 + alpha_Br (T - T0)] (1 - R_irr) (E8) [T].
  double remanence(const TorqueMotorParameters &motor, double T, double T0);

  /// Resistance of the circuit that carries the control current i: one coil (push-pull, D7) or both
  /// in series (series-aiding), R_c(T) = R_c (1 + alpha_Cu (T - 20 degC)) per coil (2.1) [Ohm].
  double coil_resistance(const TorqueMotorParameters &motor, double T);
  /// Its inductance: one coil's L_c, or 4 L_c for two tightly coupled coils in series (2.1) [H].
  double coil_inductance(const TorqueMotorParameters &motor);

  /// Pilot-stage dimensions at T (2.3). The null gap changes with the mismatch of body, nozzles and
  /// flapper: x0(T) = x0 + (alpha_body S - 2 alpha_nozzle L_n - alpha_flapper w_f)(T - T0)/2.
  struct PilotStageGeometry
  {
    double fixed_orifice_diameter; ///< D_0(T) [m]
    double fixed_orifice_length;   ///< l_0(T) [m]
    double nozzle_diameter;        ///< D_N(T) [m]
    double land_diameter;          ///< D_land(T) [m]
    double null_gap;               ///< x0(T) [m]
  };
  PilotStageGeometry pilot_stage_geometry(const PilotStageParameters &pilot, const ArmatureParameters &armature,
                                          const ThermalExpansion &alpha, double T, double T0);

  /// Spool areas at T (spool and sleeve expand with alpha_spool).
  struct SpoolGeometry
  {
    double control_area;  ///< A_v(T) [m^2]
    double feedback_area; ///< A_fb(T) [m^2]
  };
  SpoolGeometry spool_geometry(const SpoolParameters &spool, const ThermalExpansion &alpha, double T, double T0);

  /// A temperature law and the range of temperatures its source supports: beyond it the law is
  /// extrapolated (doc/method.md, "Temperature laws and their ranges").
  struct LawRange
  {
    std::string law;   ///< what it gives, and its equation
    double lowest;     ///< [degC]
    double highest;    ///< [degC]
    std::string basis; ///< where the range comes from
  };
  /// The ranges of the laws the oil, the magnets, the spring tube and the thermal expansion follow,
  /// with the viscosity law `Fluid/Viscosity law' selects.
  std::vector<LawRange> law_ranges(const FluidParameters &fluid);
  /// One sentence naming the laws whose range `temperatures' leave (lowest to highest of them), or
  /// empty if none; `entry' names where the temperatures come from.
  std::string beyond_law_ranges(const std::vector<LawRange> &ranges, const std::vector<double> &temperatures,
                                const std::string &entry);
} // namespace servodrift::laws
