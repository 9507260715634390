#pragma once
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Fits": degrees of the general polynomial surfaces fitted to each table (besides the
  /// paper's forms E25-E28, which are always fitted).
  struct FitParameters
  {
    static constexpr const char *subsection = "Fits";
    std::vector<int> torque_motor_degrees;  ///< temperature, angle, current
    std::vector<int> spring_tube_degrees;   ///< temperature
    std::vector<int> fixed_orifice_degrees; ///< temperature, pressure difference
    std::vector<int> nozzle_flapper_degrees; ///< temperature, gap, pressure difference

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
