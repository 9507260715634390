#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Operating conditions" (model.md 2.1).
  struct OperatingConditions
  {
    static constexpr const char *subsection = "Operating conditions";
    double supply_pressure;       ///< p_s, gauge [Pa]
    double return_pressure;       ///< p_r, gauge [Pa]
    double reference_temperature; ///< T0, at which the valve is built and nulled [degC]
    double rated_current;         ///< rated differential coil current [A]
    double ambient_pressure;      ///< absolute pressure of gauge zero, for cavitation checks [Pa]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// p_r < p_s, a rated current > 0. Throws InputError naming the entry.
    void validate() const;
  };
} // namespace servodrift
