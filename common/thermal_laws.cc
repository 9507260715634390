#include "common/thermal_laws.h"

#include "common/error.h"
#include "common/units.h"

#include <algorithm>
#include <cmath>

namespace servodrift::laws
{
  Oil::Oil(const FluidParameters &fluid, double reference_temperature)
    : fluid(fluid)
    , T0(reference_temperature)
  {}

  void Oil::check_temperature(double T, const char *what) const
  {
    if (!(T >= fluid.minimum_temperature && T <= fluid.maximum_temperature))
      throw InputError(std::string(what) + " " + format_number(T) +
                       " degC is outside the window of the oil's viscosity law [" +
                       format_number(fluid.minimum_temperature) + ", " +
                       format_number(fluid.maximum_temperature) +
                       "] degC (set `Fluid/Minimum temperature' and `Fluid/Maximum temperature' only "
                       "where the law holds)");
  }

  ValueAndSlope Oil::kinematic_viscosity(double T) const
  {
    check_temperature(T, "oil temperature");
    if (fluid.viscosity_law == FluidParameters::ViscosityLaw::vogel)
      {
        // E16: nu = A exp(B/(T + C)),  dnu/dT = -nu B/(T + C)^2
        const double u = T + fluid.vogel_c;
        const double nu = fluid.vogel_a * std::exp(fluid.vogel_b / u);
        return {nu, -nu * fluid.vogel_b / (u * u)};
      }
    // E14 without its pressure term: nu = nu0 exp(-alpha_nu (T - T0))
    const double nu = fluid.reference_viscosity * std::exp(-fluid.viscosity_temperature_coefficient * (T - T0));
    return {nu, -fluid.viscosity_temperature_coefficient * nu};
  }

  ValueAndSlope Oil::density(double T) const
  {
    check_temperature(T, "oil temperature");
    // E15 without its pressure term
    return {fluid.reference_density * (1.0 - fluid.density_temperature_coefficient * (T - T0)),
            -fluid.reference_density * fluid.density_temperature_coefficient};
  }

  double Oil::dynamic_viscosity(double T) const
  {
    return density(T).value * kinematic_viscosity(T).value;
  }

  double Oil::effective_bulk_modulus(double T) const
  {
    check_temperature(T, "oil temperature");
    return fluid.bulk_modulus * (1.0 - fluid.bulk_modulus_temperature_coefficient * (T - T0));
  }

  double youngs_modulus(const SpringTubeParameters &tube, double T)
  {
    // E12
    return tube.youngs_modulus * (1.0 - tube.modulus_temperature_coefficient * (T - tube.reference_temperature));
  }

  SpringTubeGeometry spring_tube_geometry(const SpringTubeParameters &tube, const ThermalExpansion &alpha, double T)
  {
    // E13: D, d, l (and the flange and collar, one piece with the tube) all scale with 1 + alpha_s (T - T_ref)
    const double T_ref = tube.reference_temperature;
    return {expanded(tube.outer_diameter, alpha.spring_tube, T, T_ref),
            expanded(tube.inner_diameter, alpha.spring_tube, T, T_ref),
            expanded(tube.length, alpha.spring_tube, T, T_ref),
            expanded(tube.base_flange_diameter, alpha.spring_tube, T, T_ref),
            expanded(tube.base_flange_height, alpha.spring_tube, T, T_ref),
            expanded(tube.top_collar_diameter, alpha.spring_tube, T, T_ref),
            expanded(tube.top_collar_height, alpha.spring_tube, T, T_ref)};
  }

  TorqueMotorGeometry torque_motor_geometry(const TorqueMotorParameters &m, const ThermalExpansion &alpha,
                                            double T, double T0)
  {
    TorqueMotorGeometry g;
    const double H_a = expanded(m.armature_height, alpha.spring_tube, T, T0);         // set by the tube
    const double half_H_ar = 0.5 * expanded(m.armature_thickness, alpha.armature, T, T0);
    const double H_c = expanded(m.lower_pole_height, alpha.pole_pieces, T, T0);
    const double H_c_upper = expanded(m.upper_pole_thickness, alpha.pole_pieces, T, T0);
    const double H_m = expanded(m.magnet_length, alpha.magnet, T, T0);
    const double h_p = expanded(m.upper_pole_tip_protrusion, alpha.pole_pieces, T, T0);
    g.lower_gap = H_a - half_H_ar - H_c;                          // E6
    g.upper_gap = H_c_upper + H_m - h_p - H_a - half_H_ar;        // E7
    g.pivot_to_pole_distance = expanded(m.pivot_to_pole_distance, alpha.armature, T, T0);
    g.pole_face_width = expanded(m.pole_face_width, alpha.pole_pieces, T, T0);
    g.pole_face_length = expanded(m.pole_face_length, alpha.pole_pieces, T, T0);
    g.armature_thickness = 2.0 * half_H_ar;
    g.magnet_length = H_m;
    g.magnet_area = expanded(m.magnet_width, alpha.magnet, T, T0) * expanded(m.magnet_depth, alpha.magnet, T, T0);
    return g;
  }

  double remanence(const TorqueMotorParameters &m, double T, double T0)
  {
    // E8
    return m.remanence * (1.0 + m.remanence_temperature_coefficient * (T - T0)) * (1.0 - m.irreversible_loss);
  }

  PilotStageGeometry pilot_stage_geometry(const PilotStageParameters &p, const ArmatureParameters &armature,
                                          const ThermalExpansion &alpha, double T, double T0)
  {
    PilotStageGeometry g;
    g.fixed_orifice_diameter = expanded(p.fixed_orifice_diameter, alpha.nozzle, T, T0);
    g.fixed_orifice_length = expanded(p.fixed_orifice_length, alpha.nozzle, T, T0);
    g.nozzle_diameter = expanded(p.nozzle_diameter, alpha.nozzle, T, T0);
    g.land_diameter = expanded(p.land_diameter, alpha.nozzle, T, T0);
    // 2.3: the two gaps are what is left of the seat span after two nozzles and the flapper
    g.null_gap = p.null_gap + 0.5 * (T - T0) *
                                (alpha.body * p.nozzle_seat_span - 2.0 * alpha.nozzle * p.nozzle_length -
                                 alpha.flapper * armature.flapper_width);
    return g;
  }

  double coil_resistance(const TorqueMotorParameters &m, double T)
  {
    const double coils = m.series_aiding ? 2.0 : 1.0;
    return coils * m.coil_resistance * (1 + m.coil_resistance_temperature_coefficient * (T - 20.0));
  }

  double coil_inductance(const TorqueMotorParameters &m)
  {
    return (m.series_aiding ? 4.0 : 1.0) * m.coil_inductance;
  }

  SpoolGeometry spool_geometry(const SpoolParameters &s, const ThermalExpansion &alpha, double T, double T0)
  {
    const double d_v = expanded(s.control_diameter, alpha.spool, T, T0);
    const double d_fb = expanded(s.feedback_diameter, alpha.spool, T, T0);
    return {0.25 * units::pi * d_v * d_v, 0.25 * units::pi * d_fb * d_fb};
  }

  std::vector<LawRange> law_ranges(const FluidParameters &fluid)
  {
    std::vector<LawRange> ranges;
    if (fluid.viscosity_law == FluidParameters::ViscosityLaw::vogel)
      ranges.push_back({"oil viscosity, Vogel (E16)", fluid.minimum_temperature, fluid.maximum_temperature,
                        "`Fluid/Minimum temperature' to `Maximum temperature'; RV-1's coefficients fit "
                        "MIL-PRF-5606 class oil at -40, 40 and 100 degC and stay within its ceiling of "
                        "2500 mm^2/s at -54 degC (model.md 2.8)"});
    else
      ranges.push_back({"oil viscosity, the paper's exponential (E14)", 40, 120, "the paper's bench [K22]"});
    ranges.push_back({"oil density (E15) and effective bulk modulus (2.8)", -55, 150,
                      "linear in T as mineral oils are from their pour point to 150 degC; beta_e's slope is "
                      "assumed (model.md 2.8)"});
    ranges.push_back({"magnet remanence (E8)", -60, 150,
                      "AlNiCo 8's reversible coefficient, -0.02 %/K in the catalogue (model.md 2.2), over "
                      "its rated range"});
    ranges.push_back({"spring-tube modulus (E12)", -60, 150,
                      "measured from -50 to 50 degC (CDA Pub. 54; model.md 1.6); a copper alloy's modulus "
                      "stays linear in T well above a third of its Debye temperature (copper's: 343 K)"});
    ranges.push_back({"thermal expansion (E6, E7, E13, 2.3)", -60, 150,
                      "mean coefficients over 20-100 degC (model.md 2.3); the instantaneous coefficients of "
                      "the valve's steels and copper alloys stay within about 10 % of them from -60 to 150 "
                      "degC"});
    return ranges;
  }

  std::string beyond_law_ranges(const std::vector<LawRange> &ranges, const std::vector<double> &temperatures,
                                const std::string &entry)
  {
    if (temperatures.empty())
      return {};
    const auto [lo, hi] = std::minmax_element(temperatures.begin(), temperatures.end());
    std::string beyond;
    for (const LawRange &r : ranges)
      if (*lo < r.lowest || *hi > r.highest)
        beyond += (beyond.empty() ? "" : "; ") + r.law + " (" + format_number(r.lowest) + " to " +
                  format_number(r.highest) + " degC: " + r.basis + ")";
    if (beyond.empty())
      return {};
    return "`" + entry + "' reach " + format_number(*lo) + " to " + format_number(*hi) +
           " degC, beyond the range its source supports of: " + beyond +
           "; each such law is extrapolated there (doc/method.md, \"Temperature laws and their ranges\")";
  }
} // namespace servodrift::laws
