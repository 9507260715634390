#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Fluid": hydraulic oil, MIL-PRF-5606 / YH-10 class (model.md 1.7, 2.8, D6).
  struct FluidParameters
  {
    static constexpr const char *subsection = "Fluid";
    enum class ViscosityLaw { vogel, paper_exponential }; ///< E16 (RV-1) or E14 (paper preset)
    ViscosityLaw viscosity_law;
    double vogel_a; ///< A in nu = A exp(B/(T + C)) [m^2/s]
    double vogel_b; ///< B [degC]
    double vogel_c; ///< C [degC]
    double reference_viscosity; ///< nu0 of E14 at T0 [m^2/s]
    double viscosity_temperature_coefficient; ///< alpha_nu of E14 [1/degC]
    double minimum_temperature; ///< validity window of the viscosity law [degC]
    double maximum_temperature; ///< [degC]
    double reference_density;   ///< rho0 at T0 (E15) [kg/m^3]
    double density_temperature_coefficient; ///< alpha_rho (E15) [1/degC]
    double bulk_modulus;        ///< beta_e at T0 [Pa]
    double bulk_modulus_temperature_coefficient; ///< beta_e = beta_e0 (1 - c (T - T0)) [1/degC]
    double vapour_pressure;     ///< absolute [Pa]
    double air_release_pressure; ///< absolute [Pa]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// The viscosity law's window: min < max, above E16's singularity. Throws InputError naming the entry.
    void validate() const;
    /// The table, drift and reference temperatures inside the window; a positive, finite viscosity and
    /// density at every table temperature (E14-E16). Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
    /// beta_e > 0 at every drift temperature (2.8). Throws InputError naming the entry.
    void validate_dynamic_model(const ValveDescription &valve) const;
  };
} // namespace servodrift
