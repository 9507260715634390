#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// The build deviations of one side of the pilot bridge (issue 25): left is the side of p_L.
  struct SideDeviations
  {
    double orifice_diameter = 0;         ///< d_0,side - d_0 [m]
    double nozzle_diameter = 0;          ///< d_N,side - d_N [m]
    double null_gap = 0;                 ///< x0,side - x0: this side's gap at x_f = 0 [m]
    double orifice_discharge_factor = 1; ///< C_d0,side / C_d0 (edge quality) [1]
    double nozzle_discharge_factor = 1;  ///< C_dN,side / C_dN (edge quality) [1]
  };

  /// Subsection "Asymmetry": a valve built off nominal, left and right (issue 25, model.md D8, E31-E39).
  /// Every entry is a deviation from the nominal value of its own subsection (default 0: the
  /// symmetric valve); the assembly offsets theta_s, theta_m, x_n stay in "Offsets".
  struct AsymmetryParameters
  {
    static constexpr const char *subsection = "Asymmetry";
    SideDeviations left, right;
    double lower_gap_mismatch; ///< torque motor: g_1 - g_2 at theta = 0 [m]
    double left_remanence;     ///< (B_r,left magnet - B_r)/B_r [1]
    double right_remanence;    ///< (B_r,right magnet - B_r)/B_r [1]
    /// The first word of a side's entries
    static const char *side_name(bool left) { return left ? "Left" : "Right"; }

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
