#pragma once
// The time average of a field-level pilot case without a steady solution (issue 28, item 6; doc/method.md,
// "Time stepping"): a case whose steady iteration does not converge because its flow does not settle
// (the laminar jet through a wide gap oscillates; with SST a hot nozzle's cavity cycles) is marched
// in time (URANS if turbulent) from where the iteration stopped,
// with the time step of a Courant number, and reported by the mean of its results over the last part
// of the run, with their standard deviations as its spread.
#include "common/parameters/pilot_stage.h"
#include "flow/pilot_field.h"

#include <functional>

namespace servodrift::flow
{
  struct TimeAverage
  {
    /// Time averages of Q, C_d, Re, the forces and the bore pressure; the lowest absolute pressure,
    /// the largest y+ and the cavitation over the averaged time; iterations: every step's.
    PilotFieldResult mean;
    double discharge_coefficient_spread = 0; ///< standard deviation over the averaged time [1]
    double flapper_force_spread = 0;         ///< [N]
    double time_step = 0;                    ///< [s]
    double averaged_time = 0;                ///< [s]
    /// The cell and face fields averaged over the averaged time (velocities, pressure, fluxes, the
    /// turbulence model's fields, the liquid fraction; a cell cavitates if its mean liquid fraction is
    /// below 1), for the VTU of the mean flow.
    FlowFields mean_fields;
  };

  /// Marches `field' at pressure difference dp from its current fields (`Field time steps' steps at
  /// `Field time step Courant number'), averaging the last `Field averaged fraction' of them. Throws
  /// std::runtime_error if a step diverges, std::invalid_argument if nothing flows.
  /// `each_step', if set, sees every step's results (a progress report).
  TimeAverage time_average(PilotField &field, double pressure_difference, const PilotStageParameters &settings,
                           const std::function<void(unsigned int step, double time, const PilotFieldResult &)> &each_step = {});
} // namespace servodrift::flow
