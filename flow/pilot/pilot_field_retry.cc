// The retry ladder of the field-level pilot chain: the ladder as data, its driver and the ranking of
// the failed attempts (pilot_field_retry.h), and the attempts themselves on a case's PilotField
// (Chain::solve_with_retry, solve_from_rest, solve_from_k_epsilon).
#include "flow/pilot/pilot_field_retry.h"

#include "common/error.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_cases.h"
#include "flow/fv/simplec.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace servodrift::flow
{
  std::vector<Attempt> retry_ladder(Turbulence t, bool own_state)
  {
    std::vector<Attempt> ladder{Attempt::from_current_state,
                                own_state ? Attempt::through_mean_level : Attempt::from_rest_in_smaller_steps};
    if (t != Turbulence::laminar && t != Turbulence::k_epsilon)
      ladder.push_back(Attempt::from_k_epsilon_solution);
    return ladder;
  }

  void FailedAttempts::add(const std::string &how, const AttemptOutcome &o, const FlowFields &state)
  {
    last = o;
    ++count;
    list += (list.empty() ? "" : "; ") + how;
    nearest_is_last = false;
    using Kind = AttemptOutcome::Kind;
    switch (o.kind)
      {
        case Kind::stalled:
          {
            const bool on_the_way = o.level != case_level;
            list += " stalled at largest residual " + format_number(largest_residual(o.residuals)) +
                    (on_the_way ? " on the way, at " + format_number(o.level * 1e-6) + " MPa" : "");
            consider(on_the_way ? Rank::stall_on_the_way : Rank::stall_at_case_level, o,
                     "the stall nearest a steady state", state);
            break;
          }
        case Kind::diverged: list += " diverged"; break;
        case Kind::diverged_from_start:
          list += " diverged";
          consider(Rank::diverged_start, o, "its start " + how + ", the state nearest a steady state", state);
          break;
        case Kind::failed_without_state: list += " failed"; break;
        case Kind::converged: break;
      }
  }

  void FailedAttempts::consider(Rank rank, const AttemptOutcome &o, const std::string &description,
                                const FlowFields &state)
  {
    // a start's residuals in its model are not known: zero
    const Residuals residuals = o.kind == AttemptOutcome::Kind::stalled ? o.residuals : Residuals{};
    if (has_nearest && (rank > nearest_rank ||
                        (rank == nearest_rank && !(largest_residual(residuals) < largest_residual(nearest_residuals)))))
      return;
    has_nearest = true;
    nearest_rank = rank;
    nearest_residuals = residuals;
    nearest_level = o.kind == AttemptOutcome::Kind::stalled ? o.level : case_level;
    nearest_message = o.message;
    nearest_description = description;
    nearest_fields = state;
    nearest_is_last = true;
  }

  CaseOutcome FailedAttempts::outcome() const
  {
    if (!has_nearest) // as the last attempt failed: a stall of k-epsilon's solve is marched too
      return {last.k_epsilon_stalled ? CaseOutcome::Kind::stalled : CaseOutcome::Kind::failed, {}, last.message,
              last.residuals, last.level, last.k_epsilon_stalled, last.k_epsilon_stalled};
    const bool residuals_known = nearest_rank != Rank::diverged_start;
    if (count < 2 && residuals_known)
      return {CaseOutcome::Kind::stalled, {}, nearest_message, nearest_residuals, nearest_level, true};
    return {CaseOutcome::Kind::stalled, {},
            nearest_message + " (" + nearest_description + " of " + std::to_string(count) +
              (count == 1 ? " attempt: " : " attempts: ") + list + ")",
            nearest_residuals, nearest_level, residuals_known};
  }

  CaseOutcome run_ladder(const std::vector<Attempt> &ladder, const std::function<AttemptOutcome(Attempt)> &attempt,
                         const std::function<FlowFields()> &state_after,
                         const std::function<std::string(Attempt)> &describe, FailedAttempts &failed)
  {
    for (const Attempt a : ladder)
      {
        const AttemptOutcome o = attempt(a);
        if (o.kind == AttemptOutcome::Kind::converged)
          return {CaseOutcome::Kind::converged, o.result, "", {}};
        failed.add(describe(a), o, o.leaves_state() ? state_after() : FlowFields{});
      }
    return failed.outcome();
  }

  AttemptOutcome attempt_outcome(const std::function<PilotFieldResult()> &solve, const PilotField &field)
  {
    try
      {
        return {AttemptOutcome::Kind::converged, solve()};
      }
    catch (const NotConverged &e)
      {
        return {AttemptOutcome::Kind::stalled, {}, e.what(), e.residuals, field.solver().boundary_pressure("inlet")};
      }
    catch (const std::runtime_error &e)
      {
        return {AttemptOutcome::Kind::diverged, {}, e.what()};
      }
  }

  CaseOutcome Chain::solve_with_retry(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp,
                                      bool started_elsewhere)
  {
    const bool at_rest = slot->at_rest();
    const bool own_state = last && last_model == t && !started_elsewhere && last_dp != dp;
    const auto describe = [&](Attempt a) -> std::string {
      switch (a)
        {
          case Attempt::from_current_state:
            return at_rest ? "from rest" : started_elsewhere ? "from the fields given" : "from the chain's last state";
          case Attempt::through_mean_level: return "from the chain's last state through the mean pressure level";
          case Attempt::from_rest_in_smaller_steps: return "from rest in smaller steps";
          case Attempt::from_k_epsilon_solution: return "from k-epsilon's solution";
        }
      return "";
    };
    const auto attempt = [&](Attempt a) -> AttemptOutcome {
      switch (a)
        {
          case Attempt::from_current_state: return attempt_outcome([&] { return slot->solve(dp); }, *slot);
          case Attempt::through_mean_level:
            slot->set_fields(*last);
            return attempt_outcome(
              [&] {
                const PilotFieldResult between = slot->solve(std::sqrt(last_dp * dp));
                PilotFieldResult r = slot->solve(dp);
                r.iterations += between.iterations;
                return r;
              },
              *slot);
          case Attempt::from_rest_in_smaller_steps: return solve_from_rest(slot, t, h, dp);
          case Attempt::from_k_epsilon_solution: return solve_from_k_epsilon(slot, t, h, dp);
        }
      throw std::logic_error("Chain: an attempt without a way");
    };
    FailedAttempts failed(dp);
    const CaseOutcome o = run_ladder(retry_ladder(t, own_state), attempt, [&] { return slot->fields(); }, describe,
                                     failed);
    if (o.kind == CaseOutcome::Kind::converged || !failed.has_state_to_march())
      return o;
    // the nearest state is marched for the time average; its fields go to the case's VTU (a later
    // attempt, or k-epsilon's on the way to model t, wrote its own there)
    if (!failed.last_is_nearest())
      slot->set_fields(failed.nearest_state());
    if (!failure_output.empty())
      slot->write_vtu(failure_output);
    return o;
  }

  AttemptOutcome Chain::solve_from_rest(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp)
  {
    PilotFieldCase c = conditions;
    c.turbulence = t;
    slot = std::make_unique<PilotField>(settings, kind, c, h);
    slot->set_failure_output(failure_output);
    // the smaller steps for this solve only: the chain's next cases take the valve's
    slot->set_continuation_ratio(std::sqrt(settings.solution.continuation_ratio));
    const AttemptOutcome o = attempt_outcome([&] { return slot->solve(dp); }, *slot);
    slot->set_continuation_ratio(settings.solution.continuation_ratio);
    return o;
  }

  AttemptOutcome Chain::solve_from_k_epsilon(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp)
  {
    PilotFieldCase c = conditions;
    c.turbulence = Turbulence::k_epsilon;
    auto k_epsilon = std::make_unique<PilotField>(settings, kind, c, h);
    k_epsilon->set_failure_output(failure_output);
    if (last && last_model == t)
      k_epsilon->set_fields(*last);
    const CaseOutcome start = solve_with_retry(k_epsilon, Turbulence::k_epsilon, h, dp, true);
    if (start.kind != CaseOutcome::Kind::converged) // no state of model t: `slot' keeps the last attempt's
      {
        AttemptOutcome o{AttemptOutcome::Kind::failed_without_state, {}, start.message, start.residuals, start.level};
        o.k_epsilon_stalled = start.kind == CaseOutcome::Kind::stalled;
        return o;
      }
    c.turbulence = t;
    const auto model_t_from_k_epsilon = [&] {
      auto field = std::make_unique<PilotField>(settings, kind, c, h);
      field->set_failure_output(failure_output);
      field->set_fields(k_epsilon->fields());
      return field;
    };
    auto model_t = model_t_from_k_epsilon();
    AttemptOutcome o = attempt_outcome(
      [&] {
        PilotFieldResult r = model_t->solve(dp);
        r.iterations += start.result.iterations + start.result.coarse_mesh_iterations;
        return r;
      },
      *model_t);
    if (o.kind == AttemptOutcome::Kind::diverged)
      {
        // model t set afresh into k-epsilon's solution, the state its time average may march from
        // (at 90 degC, Launder-Sharma's orifice at 15.45 MPa diverges in the steady iteration from
        // there but settles when marched; bench_orifice_march 90)
        model_t = model_t_from_k_epsilon();
        o.kind = AttemptOutcome::Kind::diverged_from_start;
      }
    slot = std::move(model_t); // a stall is model t's state at the case's level
    return o;
  }
} // namespace servodrift::flow
