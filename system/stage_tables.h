#pragma once
// The system model's only input besides the valve description: the four coefficient tables, read
// from <output>/tables, and their interpolants. The system model never knows which level (reduced
// order or field) produced a table (D13).
#include "common/grid_function.h"
#include "common/table.h"
#include "common/valve_description.h"

#include <optional>
#include <string>
#include <vector>

namespace servodrift::system
{
  struct StageTables
  {
    Table torque_motor{schemas::torque_motor};
    Table spring_tube{schemas::spring_tube};
    Table fixed_orifice{schemas::fixed_orifice};
    Table nozzle_flapper{schemas::nozzle_flapper};
    /// the pilot flows at wider bores, where the flow stage made them (`Pilot stage/Bore sensitivity/Tables')
    std::optional<Table> fixed_orifice_bore, nozzle_flapper_bore;
    std::vector<std::string> warnings; ///< e.g. a table made with other parameters
    std::vector<std::string> notes;    ///< what the reader should know that is not wrong (flag 6 rows)

    /// Reads and checks the four tables from `directory'.
    static StageTables read(const std::string &directory, const ValveDescription &valve);
    /// These tables with the pilot stage's of another flow model, <table>.<variant>.csv in
    /// `directory' (the model-form alternatives), read and checked alike.
    StageTables with_pilot_variant(const std::string &directory, const std::string &variant) const;
  };

  /// Interpolants of the tables: what the valve model evaluates.
  struct StageFunctions
  {
    explicit StageFunctions(const StageTables &tables);
    GridFunction torque;              ///< T_em(T, theta, i) [N*m]
    GridFunction stiffness;           ///< K_a(T) [N*m/rad]
    GridFunction orifice_conductance; ///< Q_0/sqrt(dp)(T, dp) [m^3/(s*Pa^0.5)]; 0 at dp = 0
    GridFunction orifice_discharge;   ///< C_d0(T, dp) [1]
    GridFunction nozzle_conductance;  ///< Q_N/sqrt(dp)(T, gap, dp); 0 at dp = 0
    GridFunction nozzle_discharge;    ///< C_dn(T, gap, dp) [1]
    GridFunction flapper_force;       ///< F(T, gap, dp) [N]
    /// A side's bore: ln(Q(D + step)/Q(D)) and the same of the flapper force, on the bore tables'
    /// few points, with their steps [m]; empty without bore tables
    struct BoreSensitivity
    {
      GridFunction log_flow_ratio;
      std::optional<GridFunction> log_force_ratio; ///< the nozzle's
      double step;
    };
    std::optional<BoreSensitivity> orifice_bore, nozzle_bore;
  };
} // namespace servodrift::system
