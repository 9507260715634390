#include "tests/support/test_support.h"

#include "common/stage_output.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/dynamics.h"
#include "tests/support/reduced_order_valve.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

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

  const ReducedOrderValve &shared_reduced_order_valve(const std::vector<std::string> &overrides)
  {
    static std::map<std::vector<std::string>, std::unique_ptr<ReducedOrderValve>> made;
    auto &valve = made[overrides];
    if (!valve)
      valve = std::make_unique<ReducedOrderValve>(overrides);
    return *valve;
  }

  ReducedOrderValve::ReducedOrderValve(const std::vector<std::string> &overrides)
    : description(valve(overrides))
    , tables(write_reduced_order_tables(description))
    , model(description, system::StageTables::read(tables, description))
  {}

  system::ValveDynamics ReducedOrderValve::dynamics(double T, system::HeldParts held,
                                                    const system::Offsets &offsets) const
  {
    return system::ValveDynamics(model.equations(T, offsets), system::amplifier_resistance(description),
                                 description.operating.rated_current, held);
  }

  double scaled_rates(const system::ValveDynamics &d, const system::ValveState &s, double command)
  {
    std::vector<double> y = d.vector_of(s), f(y.size());
    d.rates(y.data(), command, f.data());
    const double w_ref = std::sqrt(d.equations().spring_stiffness() / d.equations().inertia());
    double worst = 0;
    for (std::size_t k = 0; k < y.size(); ++k)
      worst = std::max(worst, std::abs(f[k]) / (d.scales()[k] * w_ref));
    return worst;
  }
} // namespace servodrift::test
