#pragma once
#include "common/parameters/model_level.h"

#include <string>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Spring tube" (model.md 1.6, 2.4, D5, C3). Dimensions and E at its own reference
  /// temperature (20 degC for RV-1, C3).
  struct SpringTubeParameters
  {
    static constexpr const char *subsection = "Spring tube";
    ModelLevel model_level;  ///< reduced-order (E11-E13) or field (D12, model.md 4.3)
    double youngs_modulus;   ///< E_ref at the reference temperature [Pa]
    double reference_temperature; ///< T_ref of E, D, d, l [degC]
    double modulus_temperature_coefficient; ///< eta: E = E_ref (1 - eta (T - T_ref)) [1/degC]
    double poisson_ratio;    ///< nu [1]
    double outer_diameter;   ///< D [m]
    double inner_diameter;   ///< d [m]
    double length;           ///< l [m]
    double yield_strength;   ///< [Pa]
    // optional ends of one piece with the tube (zero height: none); dimensions at T_ref
    double base_flange_diameter; ///< outer diameter of the clamped base flange [m]
    double base_flange_height;   ///< its height below the thin section (0: none) [m]
    double top_collar_diameter;  ///< outer diameter of the top collar [m]
    double top_collar_height;    ///< its height above the thin section (0: none) [m]
    // axisymmetric n = 1 field model (structure/spring_tube_field)
    unsigned int field_element_degree; ///< FE_Q degree of the displacement harmonics (1..4)
    unsigned int field_wall_layers;    ///< element layers through the wall at resolution 1
    double field_aspect_ratio;         ///< axial / radial element size in the wall [1]
    double field_mesh_resolution;      ///< scales every element count [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// Positive dimensions, d < D. Throws InputError naming the entry.
    void validate() const;
    /// A bore, nu < 0.5 and ends that can be meshed; for the field level. Throws InputError naming the entry.
    void validate_field_model() const;
    /// E(T) > 0 at every table temperature (E12). Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
  };
} // namespace servodrift
