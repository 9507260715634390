// The retry ladder of a field-level pilot case, as data: the attempts a case gets (retry_ladder),
// what each came to as a value (AttemptOutcome), the one driver that runs them in order
// (run_ladder), and the ranking of the failed attempts' states (FailedAttempts) that decides what
// the case comes to (CaseOutcome). Chain (flow/pilot/pilot_field_chain.cc, pilot_field_retry.cc) performs
// the attempts on a PilotField; the driver and the ranking know only the outcomes, and are tested
// against a scripted fake (pilot_field_retry_test.cc).
#pragma once

#include "flow/fv/flow_state.h"
#include "flow/pilot/pilot_field.h"

#include <functional>
#include <string>
#include <vector>

namespace servodrift::flow
{
  using Turbulence = FlowSolverParameters::Turbulence;

  /// One way to attempt a case, in the order the ladder tries them.
  enum class Attempt
  {
    /// from the state the case holds: the chain's last converged fields, the fields given (another
    /// gap's), or rest
    from_current_state,
    /// from the chain's last converged state of the case's model, through the geometric mean of the
    /// two pressure levels (half the step, in the logarithm)
    through_mean_level,
    /// from rest, in half the steps of `Field solution/Continuation ratio' (in the logarithm)
    from_rest_in_smaller_steps,
    /// the case solved with the two-layer k-epsilon (on its own ladder), and the case's model
    /// started from that solution at the same pressure level, as users of CFD codes start SST from
    /// a converged k-epsilon field
    from_k_epsilon_solution
  };

  /// The ladder of a case of model t: its current state; then, so that the retry does not repeat
  /// the path that failed, the chain's own last state through the mean level if it has one of this
  /// model at another level (`own_state'), else rest in smaller steps; and for the models less
  /// robust than the two-layer k-epsilon (SST, Launder-Sharma), k-epsilon's solution. SST's
  /// cavitating orifice at 20.6 MPa diverges on its own as the cavity grows by thousands of cells in
  /// a few iterations; from k-epsilon's cavity it converges (doc/validation.md, "Robustness").
  std::vector<Attempt> retry_ladder(Turbulence t, bool own_state);

  /// What an attempt came to.
  struct AttemptOutcome
  {
    enum class Kind
    {
      converged,
      stalled,             ///< NotConverged: its state is the case's model's, at `level'
      diverged,            ///< no state to march from
      diverged_from_start, ///< the model diverged from k-epsilon's solution: that start is a state
      failed_without_state ///< k-epsilon's solve failed: no state of the case's model
    } kind;
    PilotFieldResult result{}; ///< converged
    std::string message{};     ///< the failure's
    Residuals residuals{};     ///< stalled: at the stall
    double level = 0;          ///< stalled (failed_without_state: k-epsilon's stall): the pressure level of its state [Pa]
    bool k_epsilon_stalled = false; ///< failed_without_state: k-epsilon's solve stalled (else it diverged)
    /// Whether the attempt left a state of the case's model to march from.
    bool leaves_state() const { return kind == Kind::stalled || kind == Kind::diverged_from_start; }
  };

  /// What a case came to: converged, stalled (the nearest state is in the case's field, to march
  /// from for its time average), or failed (no state to march from: flagged).
  struct CaseOutcome
  {
    enum class Kind
    {
      converged,
      stalled,
      failed
    } kind;
    PilotFieldResult result{}; ///< converged
    std::string message{};     ///< otherwise: why, with the list of attempts if there were several
    Residuals residuals{};     ///< stalled: the nearest state's, where known
    /// stalled: the pressure level of the nearest state [Pa] (the case's, or one on the way to it)
    double level = 0;
    /// stalled: `residuals' are the nearest state's (not so for a start that diverged: its
    /// residuals in the case's model are not known)
    bool residuals_known = false;
    /// stalled: the nearest state is k-epsilon's stall, from which the case's model was to start
    /// (no attempt of its own left one)
    bool k_epsilon_state = false;
  };

  /// The failed attempts of one case, in order, and the state its time average marches from: the
  /// one nearest the case's steady state. Ranked: a stall at the case's pressure level, the model's
  /// own state; then the start of an attempt that diverged from another model's solution at that
  /// level (k-epsilon's, from which SST or Launder-Sharma started); then a stall on the way (an
  /// intermediate level of the continuation, whose residuals are another problem's); among stalls
  /// of one rank, the smallest largest scaled residual. Why: a far stall can march into another
  /// motion whose steps stop at their iteration cap while a near one of the same case averages
  /// calmly (Launder-Sharma's orifice at 15.45 MPa and 100 degC: continuity 0.20 against 5e-3;
  /// doc/changes.md, issue 28: which stall a refused march starts from); at 90 degC, marched from
  /// its stall on the way at 6.26 MPa, it diverged at its first step, from k-epsilon's solution it
  /// settles (bench_orifice_march 90). k-epsilon's solution does not outrank a stall at the case's
  /// level: SST's nozzle at 40 um, 3.09 MPa and 120 degC, marched from it, still drifts after 9 000
  /// steps (flagged 2), from its own stall (continuity 0.037) it averages (doc/changes.md, issue 28:
  /// k-epsilon's solution as a state to march).
  class FailedAttempts
  {
  public:
    /// The attempts at a case of pressure difference dp [Pa].
    explicit FailedAttempts(double dp)
      : case_level(dp)
    {}
    /// Attempt `how' failed as `o' says, leaving `state' (of the case's model) where it left one.
    void add(const std::string &how, const AttemptOutcome &o, const FlowFields &state);

    /// Whether an attempt left a state to march from (a stall, or a start that diverged).
    bool has_state_to_march() const { return has_nearest; }
    /// Whether the last attempt's state is the nearest (then the case's field holds it already).
    bool last_is_nearest() const { return nearest_is_last; }
    const FlowFields &nearest_state() const { return nearest_fields; }

    /// What the case came to: stalled with the nearest state, its message followed by the list of
    /// attempts if there was more than one (a single stall keeps its message); or, if no attempt
    /// left a state, as the last attempt failed (a stall of k-epsilon's solve too).
    CaseOutcome outcome() const;

  private:
    /// How near the case's steady state an attempt's state is, nearest first.
    enum class Rank
    {
      stall_at_case_level,
      diverged_start, ///< another model's solution at the case's level
      stall_on_the_way
    };
    /// Keeps the state if it is nearer than the nearest so far (the first of equal ones stands).
    void consider(Rank rank, const AttemptOutcome &o, const std::string &description, const FlowFields &state);

    double case_level; ///< [Pa]
    AttemptOutcome last;
    bool has_nearest = false;
    Rank nearest_rank = Rank::stall_on_the_way;
    std::string nearest_message;
    std::string nearest_description; ///< `the stall nearest a steady state', ...
    Residuals nearest_residuals;     ///< zero for a start: its model's residuals there are not known
    double nearest_level = 0;        ///< [Pa]
    FlowFields nearest_fields;
    bool nearest_is_last = false; ///< no attempt came after the nearest
    unsigned int count = 0;
    std::string list; ///< `<how> stalled at largest residual <r>[ on the way, at <p> MPa]', `<how> diverged', ...
  };

  /// Runs `ladder': each attempt by `attempt' until one converges, each failure ranked in `failed'
  /// with the state `state_after' reads after it (the case's field) where it left one; `describe'
  /// names an attempt in the list of attempts. Returns the converged result, or the ranking's
  /// outcome (its nearest state: failed.nearest_state()).
  CaseOutcome run_ladder(const std::vector<Attempt> &ladder, const std::function<AttemptOutcome(Attempt)> &attempt,
                         const std::function<FlowFields()> &state_after,
                         const std::function<std::string(Attempt)> &describe, FailedAttempts &failed);

  /// The outcome of a solve: converged with its result, or the failure it threw as a value
  /// (NotConverged: stalled with its residuals, at the inlet's pressure level; any other
  /// std::runtime_error: diverged).
  AttemptOutcome attempt_outcome(const std::function<PilotFieldResult()> &solve, const PilotField &field);
} // namespace servodrift::flow
