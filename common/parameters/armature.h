#pragma once
namespace dealii { class ParameterHandler; }

namespace servodrift
{
  /// Subsection "Armature": the armature-flapper assembly (model.md 1.12, 1.13, 2.5).
  struct ArmatureParameters
  {
    static constexpr const char *subsection = "Armature";
    double pivot_to_nozzle_distance; ///< r, x_f = r theta (E30) [m]
    double inertia;                  ///< J_a [kg*m^2]
    double damping;                  ///< B_a [N*m*s/rad]
    double flapper_width;            ///< w_f at the nozzles [m]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace servodrift
