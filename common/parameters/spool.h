#pragma once
namespace dealii { class ParameterHandler; }

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
    double viscous_damping;   ///< B_v at T0, scales with mu(T) [N*s/m]
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

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace servodrift
