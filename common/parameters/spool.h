#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Spool": three-way brake pressure valve with integrated pressure feedback
  /// (model.md 1.1, 1.17, 1.18, 2.7, C5).
  struct SpoolParameters
  {
    static constexpr const char *subsection = "Spool";
    double control_diameter;  ///< d_v, A_v = pi d_v^2/4 [m]
    double feedback_diameter; ///< d_fb, A_fb = pi d_fb^2/4 [m]
    double mass;              ///< m_v [kg]
    double spring_rate;       ///< k_s [N/m]
    double spring_preload;    ///< F_s0 [N]
    double area_gradient;     ///< W [m]
    double overlap;           ///< x_ov, positive = overlapped [m]
    double stroke_limit;      ///< |x_v| <= stroke_limit [m]
    double discharge_coefficient; ///< C_dv [1]
    double jet_angle;         ///< [deg]
    double radial_clearance;  ///< c_r [m]
    double land_length;       ///< L of the sealing lands, for B_v [m]
    double brake_volume;      ///< V_B [m^3]
    enum class BrakePort { brake_volume, blocked_port };
    BrakePort brake_port;     ///< what the brake port feeds (E37; dynamics)
    double port_volume;       ///< volume of the valve's own port passage [m^3]
    double minimum_leak_length; ///< floor of the lap leak length x_ov -+ x_v (E36, C14) [m]
    double laminar_transition_number; ///< lambda_c of the tanh blend of the metering edges (E20, C14) [1]
    double stop_stiffness;    ///< stiffness of the stroke stops [N/m]
    double stop_damping_ratio; ///< c = 2 zeta sqrt(k m_v) of the stops [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// Positive diameters, overlap and radial clearance (E36), a stroke beyond the overlap. Throws
    /// InputError naming the entry.
    void validate() const;
    /// Positive mass (E35) and volumes (E37). Throws InputError naming the entry.
    void validate_dynamic_model() const;
  };
} // namespace servodrift
