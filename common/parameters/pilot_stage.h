#pragma once
#include "common/parameters/model_level.h"
#include "common/parameters/pilot_field.h"

#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Pilot stage/Reduced order": the closed forms of the pilot flows (E21-E23) or the
  /// paper's fits (D2)
  struct PilotReducedOrderParameters
  {
    static constexpr const char *subsection = "Reduced order";
    enum class OrificeLaw { lichtarowicz, paper_fit };       ///< E21 or E26 (D2)
    enum class NozzleLaw { curtain, paper_fit };             ///< E22 or E27 T-part (D2)
    enum class FlapperForceLaw { momentum, paper_table };    ///< E23 or section 3 item 10 (D2)
    OrificeLaw fixed_orifice_law;
    NozzleLaw nozzle_law;
    double nozzle_discharge_coefficient; ///< C_d,inf of the curtain orifice (E22) [1]
    FlapperForceLaw flapper_force_law;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };

  /// Subsection "Pilot stage/Bore sensitivity/Tables": the pilot tables at wider bores, for a side built
  /// to another bore (Asymmetry, Tolerances)
  struct BoreSensitivityParameters
  {
    static constexpr const char *subsection = "Bore sensitivity";
    /// whether the flow stage tabulates them (automatic: when a study needs them at the field
    /// level; ValveDescription::needs_bore_tables)
    enum class Tables { automatic, on, off };
    Tables tables;
    double step; ///< [m]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };

  /// Subsection "Pilot stage": fixed orifices, nozzles and the nozzle-flapper gap (model.md 1.8-1.10,
  /// 1.14, 2.6, D11), dimensions at the reference temperature T0; the settings of each level in
  /// its own subsection.
  struct PilotStageParameters
  {
    static constexpr const char *subsection = "Pilot stage";
    ModelLevel model_level;         ///< reduced-order (E21-E23) or field (finite volumes, 4.2)
    double fixed_orifice_diameter;  ///< D_0 [m]
    double fixed_orifice_length;    ///< l_0 [m]
    double nozzle_diameter;         ///< D_N [m]
    double land_diameter;           ///< D_land, outer diameter of the nozzle tip [m]
    double null_gap;                ///< x0 [m]
    double nozzle_seat_span;        ///< body span between the two nozzle seats [m]
    double nozzle_length;           ///< length of each nozzle from its seat to its tip [m]
    double control_cavity_volume;   ///< V_0 (E33; dynamics) [m^3]

    PilotReducedOrderParameters reduced_order;
    PilotFieldMeshParameters field_mesh;
    PilotFieldSolutionParameters field_solution;
    PilotTimeAverageParameters time_average;
    BoreSensitivityParameters bore_sensitivity;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// Positive dimensions, x0 <= D_N/4 (E32), D_land > D_N (E22). Throws InputError naming the entry.
    void validate() const;
    /// The null gap open at every table temperature (2.3). Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
    /// V_0 above the volume the spool end sweeps (E33). Throws InputError naming the entry.
    void validate_dynamic_model(const ValveDescription &valve) const;
  };
} // namespace servodrift
