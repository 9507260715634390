#include "tests/support/test_support.h"

#include "common/stage_output.h"
#include "flow/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"

namespace servodrift::test
{
  ValveDescription valve(std::vector<std::string> overrides)
  {
    // the reduced-order torque motor, spring tube and pilot stage unless a test asks for the field
    // level (the system-model tests compare with model.md's closed-form figures)
    overrides.insert(overrides.begin(), "Pilot stage/Model level=reduced-order");
    overrides.insert(overrides.begin(), "Torque motor/Model level=reduced-order");
    overrides.insert(overrides.begin(), "Spring tube/Model level=reduced-order");
    // the dynamics only where a test asks for them (its checks need the torque table to reach the
    // nozzle contacts and the sine amplitudes, which some static tests narrow on purpose)
    overrides.insert(overrides.begin(), "Dynamics/Enabled=false");
    overrides.push_back("Output/Directory=" + temporary_directory());
    overrides.push_back("Output/Progress=none");
    return load_valve_description("", overrides);
  }

  std::string write_reduced_order_tables(const ValveDescription &v)
  {
    magnetics::run(v);
    structure::run(v);
    flow::run(v);
    return tables_directory(v);
  }
} // namespace servodrift::test
