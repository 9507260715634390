#pragma once
// model.md C9: no static reading of the paper's model reproduces its drift curves (Figs. 15-16).
// The leading hypothesis is that the paper read its dynamic model at a fixed simulation time, before
// the steady state. At each drift temperature this integrates the start-up of the valve from rest
// (supply switched on with every pressure at return, armature and spool centred) for theta_d = 0
// and for each deviation angle of the study, at i = 0 (spool displacement, the paper's Fig. 15) and at the
// rated current (brake pressure, Fig. 16), reads the deviations (E40) at fixed times, and compares
// their scale-free shape, the slope ratio (40-50 degC)/(110-120 degC) of D9, with the paper's 11.5 and
// 10.4.
#include "common/parameters/output.h"
#include "system/valve_model.h"

#include <optional>
#include <vector>

namespace servodrift::system
{
  struct FixedTimeStudy
  {
    double deviation_angle = 0;           ///< theta_d of the deviated valve [rad]
    std::vector<double> temperatures;     ///< the drift temperatures [degC]
    std::vector<double> reading_times;    ///< [s]
    /// [reading time][temperature]: x_v(theta_d) - x_v(0) at i = 0 [m], p_B(theta_d) - p_B(0) at rated [Pa]
    std::vector<std::vector<double>> displacement_deviation, pressure_deviation;
    /// the same at the static operating points (the steady state) [m], [Pa]
    std::vector<double> static_displacement_deviation, static_pressure_deviation;
    /// [reading time]: slope ratios (d(50) - d(40))/(d(120) - d(110)); empty where a slope vanishes or
    /// the drift temperatures lack 40, 50, 110 or 120 degC
    std::vector<std::optional<double>> displacement_slope_ratio, pressure_slope_ratio;
    std::optional<double> static_displacement_slope_ratio, static_pressure_slope_ratio;
    /// the reading time whose two ratios are nearest the paper's (|ln(r/r_paper)| summed), if any
    std::optional<std::size_t> best;
  };

  /// The paper's slope ratios (D9): spool displacement 11.5, brake pressure 10.4.
  inline constexpr double paper_displacement_slope_ratio = 11.5, paper_pressure_slope_ratio = 10.4;

  /// One study per `Dynamics/Fixed-time deviation angles'.
  std::vector<FixedTimeStudy> fixed_time_study(const ValveModel &model, double amplifier_resistance,
                                               OutputParameters::Progress progress);

  /// (d(50) - d(40))/(d(120) - d(110)) of a series over the temperatures; empty if not defined.
  std::optional<double> slope_ratio(const std::vector<double> &temperatures, const std::vector<double> &values);
} // namespace servodrift::system
