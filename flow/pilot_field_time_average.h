#pragma once
// The time average of a field-level pilot case without a steady solution (issue 28, item 6; doc/method.md,
// "Time stepping"): a case whose steady iteration does not converge because its flow does not settle
// (the laminar jet through a wide gap oscillates; with SST a hot nozzle's cavity cycles) is marched
// in time (URANS if turbulent) from where the iteration stopped,
// with the time step of a Courant number, and reported by the mean of its results over the last part
// of the run, with their standard deviations as its spread and the standard errors of the means
// (batch means) as their uncertainty.
#include "common/parameters/pilot_stage.h"
#include "flow/pilot_field.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace servodrift::flow
{
  struct TimeAverage
  {
    /// Time averages of Q, C_d, Re, the forces and the bore pressure; the lowest absolute pressure,
    /// the largest y+ and the cavitation over the averaged time; iterations: every step's.
    PilotFieldResult mean;
    double discharge_coefficient_spread = 0; ///< standard deviation over the averaged time [1]
    double flapper_force_spread = 0;         ///< [N]
    /// Standard errors of the means (batch means over the averaged time): how well the run pins
    /// the mean down, which is what the valve feels (a jet or cavity cycling at 0.1-1 MHz is far
    /// above the armature's and the spool's bandwidth).
    double discharge_coefficient_uncertainty = 0; ///< [1]
    double flapper_force_uncertainty = 0;         ///< [N]
    double time_step = 0;                    ///< [s]
    double averaged_time = 0;                ///< [s]
    /// The cell and face fields averaged over the averaged time (velocities, pressure, fluxes, the
    /// turbulence model's fields, the liquid fraction; a cell cavitates if its mean liquid fraction is
    /// below 1), for the VTU of the mean flow.
    FlowFields mean_fields;
  };

  /// The standard error of the mean of a correlated series by batch means: the series cut into
  /// `batches' consecutive batches (at most one per value), the sample standard deviation of their
  /// means over sqrt(batches); 0 for fewer than two. Successive steps of a marched case are strongly
  /// correlated (a cavity's cycle spans hundreds of steps), so the values' own standard deviation
  /// over sqrt(n) would understate the error; batches longer than the correlation time are nearly
  /// independent (checked on AR(1) series, pilot_field_time_average_test.cc).
  double batch_means_standard_error(const std::vector<double> &series, std::size_t batches);

  /// Marches `field' at pressure difference dp from its current fields (`Field time steps' steps at
  /// `Field time step Courant number'), averaging the last `Field averaged fraction' of them. Throws
  /// std::runtime_error if a step diverges, std::invalid_argument if nothing flows.
  /// `each_step', if set, sees every step's results (a progress report).
  TimeAverage time_average(PilotField &field, double pressure_difference, const PilotStageParameters &settings,
                           const std::function<void(unsigned int step, double time, const PilotFieldResult &)> &each_step = {});
} // namespace servodrift::flow
