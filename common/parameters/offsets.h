#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Offsets": assembly offsets of E39 and the deviation angle of D8.
  struct OffsetParameters
  {
    static constexpr const char *subsection = "Offsets";
    double spring_tube_rest_angle; ///< theta_s [rad] (declared in degree)
    double magnetic_null;          ///< theta_m [rad] (declared in degree)
    double hydraulic_null;         ///< x_n [m]
    enum class Target { magnetic_null, spring_tube_rest_angle, hydraulic_null };
    Target deviation_target;       ///< which offset the deviation angle theta_d drives (D8)
    enum class Nulling { nulled_at_reference, as_assembled };
    Nulling nulling;               ///< D8 convention

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// No target that re-nulling removes by construction (C8). Throws InputError naming the entry.
    void validate() const;
  };
} // namespace servodrift
