#pragma once
// The system stage: from the four coefficient tables to the stage coefficients, the operating
// points, the drift maps, their plots and the report.
#include "common/fitting.h"
#include "common/table_formats.h"
#include "common/valve_description.h"
#include "system/drift_map.h"
#include "system/dynamics.h"
#include "system/model_form.h"
#include "system/stage_coefficients.h"
#include "system/stage_tables.h"
#include "system/calibration.h"
#include "system/tolerance_study.h"

#include <optional>
#include <string>
#include <vector>

namespace servodrift::system
{
  struct SystemResults
  {
    std::vector<StageCoefficients> coefficients; ///< at the drift temperatures
    DriftMap drift_map;
    PolynomialFit flow_force_fit;                ///< E28: K_f(T), quartic in T
    std::vector<std::string> warnings;
    std::vector<std::string> notes; ///< the tables' notes (StageTables::notes)
    std::vector<std::string> table_producers;    ///< producer line of each table (tells the model level)
    std::optional<DynamicsResults> dynamics;     ///< when asked for (issue 23)
    std::optional<ToleranceResults> tolerances;  ///< when asked for (issue 25)
    const CalibrationResults *calibration = nullptr; ///< the fit that made this valve (issue 26)
    /// the default's and each model-form alternative's coefficients (issue 28; only the default's
    /// when `Pilot stage/Field solution/Model-form alternatives' is empty)
    std::vector<ModelFormCoefficients> model_form;
    /// the four tables on their grids, when `Output/Formats' asks for mat or modelica
    std::vector<GriddedData> table_grids;
  };

  /// The analyses beyond the static ones (stage coefficients, operating points, drift maps).
  struct Analyses
  {
    bool dynamics = false;
    bool tolerances = false;
    const CalibrationResults *calibration = nullptr; ///< written beside, and a section in the report
  };

  /// Everything, from the tables in `tables_directory', without writing anything; the dynamics
  /// and the tolerance study too if asked for.
  SystemResults compute(const ValveDescription &valve, const std::string &tables_directory, Analyses analyses = {});

  /// The static operating points and drift map of the valve on `tables' (in memory), discarded:
  /// whether the system model can run on tables with these ranges. Writes nothing. Throws what
  /// compute() would (a TableRangeError naming the table, an InputError).
  void check_operating_points(const ValveDescription &valve, const StageTables &tables);
  /// compute() on <output>/tables, then writes system/*.csv, tables/fits.json (with E28), the
  /// plots and report.md (rank 0).
  void run(const ValveDescription &valve, Analyses analyses);
} // namespace servodrift::system
