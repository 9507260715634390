#pragma once
// The time average of a field-level pilot case without a steady solution (issue 28, item 6; doc/method.md,
// "Time stepping"): a case whose steady iteration does not converge because its flow does not settle
// (the laminar jet through a wide gap oscillates; with SST a hot nozzle's cavity cycles) is marched
// in time (URANS if turbulent) from where the iteration stopped,
// with the time step of a Courant number, and reported by the mean of its results over the last part
// of the run, with their standard deviations as its spread and the standard errors of the means
// (batch means) as their uncertainty.
#include "common/parameters/pilot_field.h"
#include "flow/pilot/pilot_field.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace servodrift::flow
{
  struct TimeAverage
  {
    /// Time averages of Q, C_d, Re (a step's: Q metered at the inlet, MeteredAt), the forces and the
    /// bore pressure; the lowest absolute pressure,
    /// the largest y+ and the cavitation over the averaged time; iterations: every step's.
    PilotFieldResult mean;
    double discharge_coefficient_spread = 0; ///< standard deviation over the averaged time [1]
    double flapper_force_spread = 0;         ///< [N]
    /// Standard errors of the means (batch means over the averaged time): how well the run pins
    /// the mean down, which is what the valve feels (a jet or cavity cycling at 0.1-1 MHz is far
    /// above the armature's and the spool's bandwidth).
    double discharge_coefficient_uncertainty = 0; ///< [1]
    double flapper_force_uncertainty = 0;         ///< [N]
    /// The same relative to the means, the force's 0 where the geometry has no flapper: what
    /// `Time average/Uncertainty limit' bounds.
    double discharge_coefficient_relative_uncertainty = 0; ///< [1]
    double flapper_force_relative_uncertainty = 0;         ///< [1]
    double courant_number = 0;               ///< of the time step, at the march's start [1]
    double time_step = 0;                    ///< [s]
    double averaged_time = 0;                ///< [s]
    unsigned int averaged_steps = 0;         ///< the steps after the start's transient
    /// Averaged steps whose implicit equations the step's iteration cap stopped short of its
    /// tolerance (a cavity collapsing within a step): a few are harmless in a mean over thousands,
    /// many say the step's equations are not solved (a step too long for the flow, or, as in the
    /// Launder-Sharma orifice's far stalls, a motion whose steps cap at any step length).
    unsigned int unconverged_steps = 0;
    /// Of those, how many each scaled residual held (the largest at the cap), in the order of
    /// residual_names: which equation a capped motion does not solve.
    std::array<unsigned int, 5> unconverged_steps_held_by{};
    /// The marches before this one whose steps the cap stopped too often (steps_converged), each
    /// followed by one at half the Courant number (`Time average/Step halvings').
    unsigned int courant_halvings = 0;
    /// The larger decorrelation_lag of the averaged C_d and flapper force series [steps]: batch
    /// means hold if the averaged steps are at least lags_per_window times it (window_spans_motion).
    unsigned int decorrelation_steps = 0;
    /// The cell and face fields averaged over the averaged time (velocities, pressure, fluxes, the
    /// turbulence model's fields, the liquid fraction; a cell cavitates if its mean liquid fraction is
    /// below 1), for the VTU of the mean flow.
    FlowFields mean_fields;
  };

  /// Each time step's implicit equations are iterated until their scaled residuals fall below this,
  /// or for at most `Time average/Step iterations': a step changes the fields little, so its
  /// residuals start low (a few iterations per step). With 1e-4 a steady laminar case marched in
  /// time stays within 1.5e-4 of its steady C_dn (pilot_field_time_average_test.cc).
  constexpr double step_tolerance = 1e-4;

  /// The largest fraction of the averaged steps that the step's iteration cap may stop short of their
  /// tolerance for the mean to stand for the case. Hot cavitating nozzles (SST; Launder-Sharma without
  /// Durbin's bound) leave up to 3.3 % of their steps capped, and a cap four times higher moved their
  /// means by less than their standard errors; the laminar 60 um gap marched at Courant 4 left 44 %
  /// capped and its C_d 16 % below Courant 1's (doc/validation.md).
  constexpr double unconverged_steps_limit = 0.1;

  /// Whether the average's steps solved their equations: at most unconverged_steps_limit of its
  /// averaged steps stopped by the cap.
  bool steps_converged(const TimeAverage &a);
  /// Which residuals held its capped steps, for a message: "continuity in 140, k in 17" (largest
  /// count first; empty if none capped).
  std::string capped_steps_held_by(const TimeAverage &a);

  /// The lag (in values) at which the sample autocorrelation of a series first falls to zero or
  /// below: a quarter of the period of a cycle, a few correlation times of noise, about a third of
  /// the length of a trend (a window that holds less than a cycle); 0 for fewer than three values or
  /// a constant series.
  std::size_t decorrelation_lag(const std::vector<double> &series);

  /// The averaged steps must hold this many decorrelation lags for batch means to hold: with 10
  /// batches each is then at least half a lag long and batches two apart a lag apart, and a cycle is
  /// spanned 1.25 times (its quarter period times 5). Averaged over less than that (a smaller
  /// Courant number with the same `Time average/Steps'), a window can hold half a cycle, whose batch
  /// means follow a trend and claim a mean several times better than it is (doc/validation.md).
  constexpr unsigned int lags_per_window = 5;

  /// A series whose standard deviation is at most this fraction of its mean does not move beyond
  /// what a step's iterations leave (they stop at scaled residuals of 1e-4): a steady flow marched,
  /// whose window needs to span nothing.
  constexpr double steady_spread = 1e-4;

  /// Whether the averaged time spans the flow's slowest motion: at least lags_per_window times its
  /// decorrelation_steps, or spreads within steady_spread of the means.
  bool window_spans_motion(const TimeAverage &a);

  /// Whether a time average stands for its case in the tables, and why not: one verdict, its reason
  /// a message's clause (empty where it stands).
  struct TimeAverageVerdict
  {
    enum class Kind
    {
      stands,            ///< the mean stands for the case (flag 5)
      steps_not_solved,  ///< more than unconverged_steps_limit of its steps capped (steps_converged)
      window_too_short,  ///< its averaged time does not span the flow's motion (window_spans_motion)
      mean_uncertain     ///< a relative standard error beyond `Time average/Uncertainty limit'
    } kind;
    std::string reason;
    bool stands() const { return kind == Kind::stands; }
  };

  /// The verdict on a finished time average, its checks in this order: the steps solved their
  /// equations, the window spans the motion, the means are within `uncertainty_limit' (relative
  /// standard errors). A mean that stands does so whatever the unsteadiness (the spread): the
  /// tables want the mean, the valve does not follow a jet or cavity cycling at 0.1-1 MHz.
  TimeAverageVerdict time_average_verdict(const TimeAverage &a, double uncertainty_limit);

  /// The standard error of the mean of a correlated series by batch means: the series cut into
  /// `batches' consecutive batches (at most one per value), the sample standard deviation of their
  /// means over sqrt(batches); 0 for fewer than two. Successive steps of a marched case are strongly
  /// correlated (a cavity's cycle spans hundreds of steps), so the values' own standard deviation
  /// over sqrt(n) would understate the error; batches longer than the correlation time are nearly
  /// independent (checked on AR(1) series, time_average_statistics_test.cc).
  double batch_means_standard_error(const std::vector<double> &series, std::size_t batches);

  /// The plan of a time average's steps: `first' steps, the last `averaged_fraction' of them averaged
  /// (the first part lets the start from the stalled iterate die out, cut once); at the end of the
  /// plan a mean whose relative standard error still exceeds `limit' gets the averaged time it asks
  /// for, up to `most' steps in all. Over times long against the flow's correlation time the error of
  /// a mean falls as 1/sqrt(time): (error/limit)^2 times the averaged steps, and a tenth more against
  /// the estimate's own scatter (about 25 % with 10 batches).
  class AveragingPlan
  {
  public:
    AveragingPlan(unsigned int first, double averaged_fraction, unsigned int most, double limit);
    unsigned int planned() const { return planned_steps; }    ///< steps in all, so far
    unsigned int averaged() const { return planned_steps - transient_steps; }
    /// Whether step (from 0) is averaged.
    bool averages(unsigned int step) const { return step >= transient_steps; }
    /// Whether step is the plan's last and the plan could still grow: then call lengthen.
    bool at_end(unsigned int step) const { return step + 1 == planned_steps && planned_steps < most_steps; }
    /// With the mean's relative error at the end of the plan and the averaged steps the window needs
    /// for that error to hold (lags_per_window decorrelation lags; 0: none): lengthens the plan if
    /// the error exceeds the limit (a NaN error too) or the window is shorter than that; returns
    /// whether it did.
    bool lengthen(double relative_error, unsigned int steps_needed = 0);

  private:
    unsigned int transient_steps, planned_steps, most_steps;
    double limit;
  };

  /// Marches `field' at pressure difference dp from its current fields (`Time average/Steps' steps at
  /// `Time average/Courant number'), averaging the last `Time average/Averaged fraction' of them. While
  /// the relative standard error of the mean C_d or flapper force exceeds `Time average/
  /// Uncertainty limit', the averaged time is lengthened by AveragingPlan, up to `Time average/
  /// Steps limit' steps in all (the start's transient is cut once), and while the averaged time
  /// does not span the flow's slowest motion (window_spans_motion); not if more than
  /// unconverged_steps_limit of the steps averaged so far were capped (steps_converged). A march
  /// whose steps the cap stopped too often is marched again from where it ended at half the Courant
  /// number, up to `Time average/Step halvings' times: a shorter step changes the fields less, so its
  /// iterations reach the tolerance within the cap more often (a cavity collapsing within a step is
  /// what stops them); the last march is returned, its iterations those of all. Throws
  /// std::runtime_error if a step diverges, std::invalid_argument if nothing flows. `each_step', if
  /// set, sees every step's results and the steps planned so far (a progress report; the steps of a
  /// march again count from 1), `before_halving' each march that is marched again.
  TimeAverage time_average(
    PilotField &field, double pressure_difference, const PilotTimeAverageParameters &settings,
    const std::function<void(unsigned int step, unsigned int planned, double time, const PilotFieldResult &)> &each_step = {},
    const std::function<void(const TimeAverage &rejected)> &before_halving = {});
} // namespace servodrift::flow
