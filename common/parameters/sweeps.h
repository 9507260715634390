#pragma once
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Sweeps": the grids of the coefficient tables and of the drift map. Every list is
  /// strictly increasing. Angles are declared in degree and stored in rad.
  struct SweepParameters
  {
    static constexpr const char *subsection = "Sweeps";
    std::vector<double> table_temperatures;   ///< temperature axis of all four tables [degC]
    std::vector<double> motor_angles;         ///< armature angles of the torque_motor table [rad]
    std::vector<double> motor_currents;       ///< coil currents of the torque_motor table [A]
    std::vector<double> pressure_fractions;   ///< pressure differences / (p_s - p_r) [1]
    std::vector<double> gap_fractions;        ///< nozzle-flapper gaps / x0 [1]
    std::vector<double> field_orifice_pressure_fractions; ///< field level: orifice dp / (p_s - p_r) [1]
    std::vector<double> field_gap_fractions;              ///< field level: gaps / x0 [1]
    std::vector<double> field_nozzle_pressure_fractions;  ///< field level: nozzle dp / (p_s - p_r) [1]
    std::vector<double> drift_temperatures;   ///< temperature axis of the drift map [degC]
    std::vector<double> deviation_angles;     ///< deviation angles theta_d of the drift map [rad]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// Every list strictly increasing, the field level's fractions > 0. Throws InputError naming the entry.
    void validate() const;
    /// The drift temperatures and `Operating conditions/Reference temperature' within the table
    /// temperatures. Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
  };
} // namespace servodrift
