#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

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
    double nozzle_contact_stiffness; ///< K_c of the flapper-nozzle contact, at the nozzle axis [N/m]
    double nozzle_contact_damping_ratio; ///< zeta_c of the contact, c_c = 2 zeta_c sqrt(K_c J_a/r^2) [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// r > 0 (E30). Throws InputError naming the entry.
    void validate() const;
    /// J_a > 0 (E29). Throws InputError naming the entry.
    void validate_dynamic_model() const;
  };
} // namespace servodrift
