#include "system/stage_tables.h"

#include <cmath>

namespace servodrift::system
{
  StageTables StageTables::read(const std::string &directory, const ValveDescription &valve)
  {
    StageTables t;
    t.torque_motor = Table::read(directory + "/torque_motor.csv", "torque_motor");
    t.spring_tube = Table::read(directory + "/spring_tube.csv", "spring_tube");
    t.fixed_orifice = Table::read(directory + "/fixed_orifice.csv", "fixed_orifice");
    t.nozzle_flapper = Table::read(directory + "/nozzle_flapper.csv", "nozzle_flapper");
    for (const Table *table : {&t.torque_motor, &t.spring_tube, &t.fixed_orifice, &t.nozzle_flapper})
      if (table->parameters_sha256 != valve.parameters_sha256)
        t.warnings.push_back("tables/" + table->name() + ".csv was made with other parameters (sha256 " +
                             table->parameters_sha256.substr(0, 12) + ", this run " +
                             valve.parameters_sha256.substr(0, 12) + "); its numbers come from that valve description");
    return t;
  }

  namespace
  {
    /// Q/sqrt(dp): smooth in dp where Q ~ sqrt(dp) is not; 0 in the laminar limit dp -> 0.
    std::function<double(const std::vector<double> &)> conductance(const Table &t)
    {
      const std::size_t q = t.column_index("flow_rate"), dp = t.column_index("pressure_difference");
      return [q, dp](const std::vector<double> &r) { return r[dp] > 0 ? r[q] / std::sqrt(r[dp]) : 0.0; };
    }
  } // namespace

  StageFunctions::StageFunctions(const StageTables &t)
    : torque(GridFunction::from_table(t.torque_motor, "table torque_motor", "torque"))
    , stiffness(GridFunction::from_table(t.spring_tube, "table spring_tube", "stiffness"))
    , orifice_conductance(GridFunction::from_table(t.fixed_orifice, "table fixed_orifice", conductance(t.fixed_orifice)))
    , orifice_discharge(GridFunction::from_table(t.fixed_orifice, "table fixed_orifice", "discharge_coefficient"))
    , nozzle_conductance(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", conductance(t.nozzle_flapper)))
    , nozzle_discharge(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", "discharge_coefficient"))
    , flapper_force(GridFunction::from_table(t.nozzle_flapper, "table nozzle_flapper", "flapper_force"))
  {}
} // namespace servodrift::system
