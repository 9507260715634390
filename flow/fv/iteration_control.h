#pragma once
// The control of the outer iteration (OpenFOAM's simpleControl, with the tests this solver needs;
// doc/method.md, "Flow core"): after each SIMPLEC or coupled iteration it judges the scaled residuals
// and decides what comes next. A state machine, unit-tested on synthetic residual histories
// (tests/unit/iteration_control_test.cc):
//   - diverged: a residual not finite, or u or continuity above 1e8 after the first 10 iterations;
//   - converged: every residual below the tolerance and the monitored quantities settled (none
//     changed by more than its relative tolerance over the monitor window);
//   - Anderson acceleration (`Acceleration depth' > 0): while the largest residual is below
//     `Acceleration start', the next iterate is the combination of the last updates; its history
//     starts again when a combination made the change grow tenfold, and stops above the start;
//   - cycle test (`Cycle window'): a window whose best largest residual is not half the last
//     window's lowers the pressure relaxation by 0.7, to 0.3 at least (the fixed point does not
//     depend on it; only the path does), and judges the new setting afresh; in coupled iterations
//     the first such window within 10 tolerances also holds the convection limiters from there on;
//   - stall test (`Stall window'): the same over the longer window; with `simplec-then-coupled'
//     SIMPLEC's stall switches to coupled iterations (judged on the cycle window from there, each
//     lowered relaxation given a whole window of its own), else the run has not converged; coupled
//     iterations that stall in turn hand back to SIMPLEC (if `resume_simplec'), once, judged on a
//     window 4 times the stall window from there;
//   - not converged: stalled, or the iteration limit.
#include "common/parameters/flow_solver.h"
#include "flow/fv/anderson_acceleration.h"
#include "flow/fv/flow_state.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace servodrift::flow
{
  /// What Anderson acceleration combines: the solver's state packed into one vector, each field
  /// divided by its own scale (set at the first pack after forget_scales(), so that the least-squares
  /// problem weighs velocity, pressure and turbulence alike), and written back.
  class AcceleratedState
  {
  public:
    virtual Eigen::VectorXd pack() = 0;
    /// Writes a combination back, bounded, with what depends on it.
    virtual void unpack(const Eigen::VectorXd &x) = 0;
    virtual void forget_scales() = 0;

  protected:
    ~AcceleratedState() = default;
  };

  /// Quantities (a flow rate, a force) whose change decides convergence with the residuals.
  struct ConvergenceMonitor
  {
    std::function<std::vector<double>()> quantities; ///< empty: none
    unsigned int window = 50;                         ///< iterations over which they must settle
    double relative_change = 1e-4;                    ///< their largest change over the window / magnitude
  };

  class IterationControl
  {
  public:
    enum class Verdict
    {
      go_on,
      converged,
      diverged,
      not_converged
    };

    /// `monitor' may be null (no monitored quantities); `turbulent': the messages name k and epsilon;
    /// `resume_simplec': stalled coupled iterations hand back to SIMPLEC, or fail the run (the
    /// solver's solve_to() of a start state: an intermediate pressure level, the liquid check).
    IterationControl(const FlowSolverParameters &settings, double tolerance, const ConvergenceMonitor *monitor,
                     bool turbulent, bool resume_simplec = true);
    ~IterationControl();

    /// Starts the next iteration; its number (from 1).
    unsigned int next() { return ++count; }
    /// Judges the residuals of the current iteration; may write an accelerated state into `state'.
    Verdict judge(const Residuals &r, AcceleratedState &state);

    unsigned int iteration() const { return count; }
    bool coupled() const { return coupled_iterations; }
    /// alpha_p of the next iteration: the setting, lowered by each cycle caught [1].
    double pressure_relaxation() const { return relaxation; }
    /// The coupled step's relaxation of its pressure update: the factor the cycles lowered alpha_p by.
    double coupled_pressure_relaxation() const { return relaxation / settings.pressure_relaxation; }
    /// The convection limiters are to be held at their last values (MomentumEquation::hold_limiters):
    /// from the first cycle caught in coupled iterations within limiter_hold_level tolerances to
    /// the end of the solve.
    bool limiters_held_now() const { return limiters_held; }
    /// Events of the last judge(), for the progress report.
    bool relaxation_lowered() const { return lowered; }
    bool switched_to_coupled() const { return switched; }
    bool switched_back_to_simplec() const { return switched_back; }
    bool limiters_hold_started() const { return hold_started; }
    /// The residuals are due on the progress report this iteration (`Report interval').
    bool report_due() const { return settings.report_interval > 0 && count % settings.report_interval == 0; }
    /// Why the run diverged or did not converge (for the error message).
    const std::string &reason() const { return why; }

    /// The limits of the tests (named in the header comment).
    static constexpr double divergence_threshold = 1e8;
    static constexpr unsigned int divergence_grace = 10;
    static constexpr double required_improvement = 0.5; ///< a window must halve the last one's best
    static constexpr double relaxation_reduction = 0.7;
    static constexpr double lowest_pressure_relaxation = 0.3;
    static constexpr double acceleration_restart_growth = 10;
    /// A cycle caught in coupled iterations holds the limiters only if its window's best largest
    /// residual is below this many tolerances.
    static constexpr double limiter_hold_level = 10;
    /// SIMPLEC after stalled coupled iterations is judged on this many stall windows (a nozzle's
    /// 1 000 iterations: Launder-Sharma's 60 um gap at 100 degC plateaus for 500).
    static constexpr unsigned int resumed_stall_window_factor = 4;

  private:
    bool monitors_settled();
    void stop_acceleration(AcceleratedState &state);
    void accelerate(double largest, AcceleratedState &state);
    void cycle_test(double largest, AcceleratedState &state);
    bool stall_test(double largest);
    std::string residual_list(const Residuals &r) const;

    FlowSolverParameters settings;
    double tolerance;
    const ConvergenceMonitor *monitor;
    bool turbulent;
    bool resume_simplec;

    unsigned int count = 0;
    double relaxation;
    bool coupled_iterations;
    bool lowered = false, switched = false, switched_back = false, limiters_held = false, hold_started = false;
    std::string why;
    std::vector<std::vector<double>> history; ///< the monitored quantities of the last window + 1 iterations
    // the stall test: the smallest largest-residual of this window and of the last; the same on the
    // shorter cycle window
    double window_best, previous_window_best, cycle_best, previous_cycle_best;
    unsigned int stall_test_from = 0; ///< the iteration of the switch to coupled iterations (0: none)
    unsigned int simplec_again_from = 0; ///< the iteration of the switch back to SIMPLEC (0: none)
    unsigned int stall_window_from = 0; ///< where the stall test's windows are counted from
    std::unique_ptr<AndersonAcceleration> anderson;
    Eigen::VectorXd accelerated_start; ///< the state the last iteration started from
    double smallest_change;
  };
} // namespace servodrift::flow
