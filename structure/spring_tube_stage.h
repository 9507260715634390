#pragma once
// The structure stage: computes the spring_tube table over the table temperatures at the model
// level chosen by `Spring tube/Model level': the beam closed form (E11-E13) or the elasticity field
// (D12; structure/spring_tube_field.h), which also writes structure/field_summary.csv and a VTU per
// temperature.
#include "common/parameters/spring_tube.h"
#include "common/table.h"
#include "common/valve_description.h"

#include <memory>

namespace servodrift::structure
{
  class SpringTubeField;
  struct SpringTubeFieldOptions;

  Table compute_spring_tube_table(const ValveDescription &valve);
  /// Computes the table and writes tables/spring_tube.csv (rank 0).
  void run(const ValveDescription &valve);

  /// The field model's mesh and element options from the valve description.
  SpringTubeFieldOptions field_options(const SpringTubeParameters &tube);
  /// The field model of the valve's tube at T [degC], solved.
  std::unique_ptr<SpringTubeField> spring_tube_field(const ValveDescription &valve, double temperature);
  /// Rated armature angle: the flapper on its nozzle, x_f = x0 = r theta (E30) [rad].
  double rated_armature_angle(const ValveDescription &valve);
} // namespace servodrift::structure
