#pragma once
#include <string>
namespace dealii { class ParameterHandler; }

namespace servodrift
{
  /// Subsection "Spring tube" (model.md 1.6, 2.4, D5, C3). Dimensions and E at its own reference
  /// temperature (20 degC for RV-1, C3).
  struct SpringTubeParameters
  {
    static constexpr const char *subsection = "Spring tube";
    std::string model_level; ///< "reduced-order" (E11-E13)
    double youngs_modulus;   ///< E_ref at the reference temperature [Pa]
    double reference_temperature; ///< T_ref of E, D, d, l [degC]
    double modulus_temperature_coefficient; ///< eta: E = E_ref (1 - eta (T - T_ref)) [1/degC]
    double poisson_ratio;    ///< nu [1]
    double outer_diameter;   ///< D [m]
    double inner_diameter;   ///< d [m]
    double length;           ///< l [m]
    double yield_strength;   ///< [Pa]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace servodrift
