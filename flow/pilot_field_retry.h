// The failed attempts at one field-level pilot case (the retry ladder of Chain::solve_with_retry,
// defined in flow/pilot_field_retry.cc): which of their stalls a time average marches from.
#pragma once

#include "flow/flow_state.h"

#include <exception>
#include <string>

namespace servodrift::flow
{
  class PilotField;

  /// The attempts of one case that failed, in order, and the state its time average marches from:
  /// the one nearest the case's steady state. Ranked: a stall (NotConverged) at the case's pressure
  /// level, the model's own state; then the start of an attempt that diverged from another model's
  /// solution at that level (k-epsilon's, from which SST or Launder-Sharma started); then a stall on
  /// the way (an intermediate level of the continuation, whose residuals are another problem's);
  /// among stalls of one rank, the smallest largest scaled residual. Why: a far stall can march into
  /// another motion whose steps stop at their iteration cap while a near one of the same case
  /// averages calmly (Launder-Sharma's orifice at 15.45 MPa and 100 degC: continuity 0.20 against
  /// 5e-3; doc/changes.md, issue 28: which stall a refused march starts from); at 90 degC, marched from its stall on the way at
  /// 6.26 MPa, it diverged at its first step, from k-epsilon's solution it settles
  /// (bench_orifice_march 90). k-epsilon's solution does not outrank a stall at the case's level:
  /// SST's nozzle at 40 um, 3.09 MPa and 120 degC, marched from it, still drifts after 9 000 steps
  /// (flagged 2), from its own stall (continuity 0.037) it averages (doc/changes.md, issue 28: k-epsilon's
  /// solution as a state to march).
  class FailedAttempts
  {
  public:
    /// The attempts at a case of pressure difference dp [Pa].
    explicit FailedAttempts(double dp)
      : case_level(dp)
    {}
    /// Call in the catch block of attempt `how' (`from rest', ...), whose state is in `field'.
    void add(const std::string &how, const PilotField &field);
    /// Call in the catch block of attempt `how' (`from k-epsilon's solution') that diverged from
    /// `field''s state, another model's steady solution at the case's pressure level, into which
    /// the model's own (a new PilotField) was set: a state to march from if no stall is at that level.
    void add_diverged_start(const std::string &how, const PilotField &field);
    /// Call in the catch block of a step that leaves no state of the case's model (the two-layer
    /// k-epsilon solve that starts another model): listed, never marched.
    void add_without_state(const std::string &how);

    /// Whether an attempt left a state to march from (a stall, or a start that diverged).
    bool has_state_to_march() const { return nearest_failure != nullptr; }
    /// Sets the nearest state's fields into `field' (of the case's model and mesh) unless `field'
    /// holds them already; true if it set them.
    bool restore_nearest(PilotField &field) const;
    /// Throws a NotConverged for the nearest state, its message followed by the list of attempts
    /// if there was more than one (a single stall is rethrown as it was), or, if no attempt left
    /// a state, rethrows the last failure.
    [[noreturn]] void rethrow() const;

  private:
    /// How near the case's steady state an attempt's state is, nearest first.
    enum class Rank
    {
      stall_at_case_level,
      diverged_start, ///< another model's solution at the case's level
      stall_on_the_way
    };
    /// Keeps `field''s state if it is nearer than the nearest so far (the first of equal ones stands).
    void consider(Rank rank, const Residuals &residuals, const std::string &description, const PilotField &field);

    double case_level; ///< [Pa]
    std::exception_ptr last_failure, nearest_failure;
    Rank nearest_rank = Rank::stall_on_the_way;
    std::string nearest_description; ///< `the stall nearest a steady state', ...
    Residuals nearest_residuals;     ///< zero for a start: its model's residuals there are not known
    FlowFields nearest_fields;
    const PilotField *nearest_field = nullptr; ///< the object that held the nearest state ...
    bool nearest_is_last = false;              ///< ... and whether no attempt in it came after
    unsigned int count = 0;
    std::string list; ///< `<how> stalled at largest residual <r>[ on the way, at <p> MPa]', `<how> diverged', ...
  };
} // namespace servodrift::flow
