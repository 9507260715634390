#pragma once
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Thermal expansion": linear expansion coefficients of each part (model.md 2.3).
  struct ThermalExpansion
  {
    static constexpr const char *subsection = "Thermal expansion";
    double spring_tube;  ///< alpha_s, BeCu [1/degC]
    double armature;     ///< alpha_ar, 1J50 [1/degC]
    double pole_pieces;  ///< alpha_c, 1J50 [1/degC]
    double magnet;       ///< alpha_m, AlNiCo 8 [1/degC]
    double body;         ///< valve body carrying the nozzle seats [1/degC]
    double nozzle;       ///< nozzles and fixed orifices [1/degC]
    double flapper;      ///< flapper [1/degC]
    double spool;        ///< spool and sleeve [1/degC]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
