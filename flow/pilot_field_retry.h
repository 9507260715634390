// The failed attempts at one field-level pilot case (the retry ladder of Chain::solve_with_retry,
// defined in flow/pilot_field_retry.cc): which of their stalls a time average marches from.
#pragma once

#include "flow/flow_state.h"

#include <exception>
#include <string>

namespace servodrift::flow
{
  class PilotField;

  /// The attempts of one case that failed, in order. Of those that stalled (NotConverged), the one
  /// nearest the case's steady state is the state its time average marches from: a stall at the
  /// case's pressure level before one on the way (an intermediate level of the continuation, whose
  /// residuals are another problem's; marched from one, Launder-Sharma's orifice at 15.45 MPa and
  /// 90 degC diverged at its first step), and among those the smallest largest scaled residual. Why:
  /// a far stall can march into another motion whose steps stop at their iteration cap while a near
  /// one of the same case averages calmly (that orifice at 100 degC: continuity 0.20 against 5e-3;
  /// doc/changes.md, twenty-second look).
  class FailedAttempts
  {
  public:
    /// The attempts at a case of pressure difference dp [Pa].
    explicit FailedAttempts(double dp)
      : case_level(dp)
    {}
    /// Call in the catch block of attempt `how' (`from rest', ...), whose state is in `field'.
    void add(const std::string &how, const PilotField &field);
    /// Call in the catch block of a step that leaves no state of the case's model (the two-layer
    /// k-epsilon solve that starts another model): listed, never marched.
    void add_without_state(const std::string &how);

    bool any_stalled() const { return nearest_failure != nullptr; }
    /// Sets the nearest stall's fields into `field' (of the case's model and mesh) unless `field'
    /// holds them already; true if it set them.
    bool restore_nearest(PilotField &field) const;
    /// Rethrows the nearest stall, its message followed by the list of attempts if there was
    /// more than one, or, if none stalled, the last failure.
    [[noreturn]] void rethrow() const;

  private:
    double case_level; ///< [Pa]
    std::exception_ptr last_failure, nearest_failure;
    bool nearest_on_the_way = true; ///< the nearest stall is on an intermediate level
    Residuals nearest_residuals;
    FlowFields nearest_fields;
    const PilotField *nearest_field = nullptr; ///< the object that held the nearest stall ...
    bool nearest_is_last = false;              ///< ... and whether no attempt in it came after
    unsigned int count = 0;
    std::string list; ///< `<how> stalled at largest residual <r>[ on the way, at <p> MPa]', `<how> diverged', ...
  };
} // namespace servodrift::flow
