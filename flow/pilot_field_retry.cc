// The retry ladder of the field-level pilot chain (Chain::solve_with_retry): the attempts at a case
// that does not converge from the chain's state, and which of their stalls a time average marches from.
#include "flow/pilot_field_retry.h"

#include "common/error.h"
#include "flow/pilot_field.h"
#include "flow/pilot_field_cases.h"
#include "flow/simplec.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace servodrift::flow
{
  void FailedAttempts::add(const std::string &how, const PilotField &field)
  {
    last_failure = std::current_exception();
    ++count;
    list += (list.empty() ? "" : "; ") + how;
    nearest_is_last = false;
    try
      {
        std::rethrow_exception(last_failure);
      }
    catch (const NotConverged &e)
      {
        const double level = field.solver().boundary_pressure("inlet");
        const bool on_the_way = level != case_level;
        list += " stalled at largest residual " + format_number(largest_residual(e.residuals)) +
                (on_the_way ? " on the way, at " + format_number(level * 1e-6) + " MPa" : "");
        consider(on_the_way ? Rank::stall_on_the_way : Rank::stall_at_case_level, e.residuals,
                 "the stall nearest a steady state", field);
      }
    catch (const std::exception &)
      {
        list += " diverged";
      }
  }

  void FailedAttempts::add_diverged_start(const std::string &how, const PilotField &field)
  {
    last_failure = std::current_exception();
    ++count;
    list += (list.empty() ? "" : "; ") + how + " diverged";
    nearest_is_last = false;
    consider(Rank::diverged_start, Residuals{}, "its start " + how + ", the state nearest a steady state", field);
  }

  void FailedAttempts::consider(Rank rank, const Residuals &residuals, const std::string &description,
                                const PilotField &field)
  {
    if (has_state_to_march() && (rank > nearest_rank || (rank == nearest_rank && !(largest_residual(residuals) <
                                                                                     largest_residual(nearest_residuals)))))
      return;
    nearest_rank = rank;
    nearest_residuals = residuals;
    nearest_description = description;
    nearest_failure = last_failure;
    nearest_fields = field.fields();
    nearest_field = &field;
    nearest_is_last = true;
  }

  void FailedAttempts::add_without_state(const std::string &how)
  {
    last_failure = std::current_exception();
    ++count;
    list += (list.empty() ? "" : "; ") + how + " failed";
    nearest_is_last = false;
  }

  bool FailedAttempts::restore_nearest(PilotField &field) const
  {
    if (!has_state_to_march() || (nearest_is_last && &field == nearest_field))
      return false;
    field.set_fields(nearest_fields);
    return true;
  }

  void FailedAttempts::rethrow() const
  {
    if (!has_state_to_march())
      std::rethrow_exception(last_failure);
    if (count < 2 && nearest_rank != Rank::diverged_start)
      std::rethrow_exception(nearest_failure);
    try
      {
        std::rethrow_exception(nearest_failure);
      }
    catch (const std::exception &e) // a stall, or the divergence of a start
      {
        throw NotConverged(std::string(e.what()) + " (" + nearest_description + " of " + std::to_string(count) +
                             (count == 1 ? " attempt: " : " attempts: ") + list + ")",
                           nearest_residuals);
      }
  }

  PilotFieldResult Chain::solve_with_retry(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp,
                                           bool started_elsewhere)
  {
    FailedAttempts failed(dp);
    const bool at_rest = slot->at_rest();
    try
      {
        return slot->solve(dp);
      }
    catch (const std::runtime_error &)
      {
        failed.add(at_rest ? "from rest" : started_elsewhere ? "from the fields given" : "from the chain's last state",
                   *slot);
      }
    const bool own_state = last && last_model == t && !started_elsewhere && last_dp != dp;
    try
      {
        if (own_state)
          {
            slot->set_fields(*last);
            const double between = std::sqrt(last_dp * dp);
            PilotFieldResult r = slot->solve(between);
            const unsigned int iterations = r.iterations;
            r = slot->solve(dp);
            r.iterations += iterations;
            return r;
          }
        return solve_from_rest(slot, t, h, dp);
      }
    catch (const std::runtime_error &)
      {
        failed.add(own_state ? "from the chain's last state through the mean pressure level" : "from rest in smaller steps",
                   *slot);
      }
    if (t != Turbulence::laminar && t != Turbulence::k_epsilon)
      {
        std::unique_ptr<PilotField> from_k_epsilon;
        try
          {
            const PilotFieldResult r = solve_from_k_epsilon(from_k_epsilon, t, h, dp);
            slot = std::move(from_k_epsilon);
            return r;
          }
        catch (const NotConverged &)
          {
            if (!from_k_epsilon) // k-epsilon's solve failed: no state of model t
              failed.add_without_state("from k-epsilon's solution");
            else
              {
                failed.add("from k-epsilon's solution", *from_k_epsilon);
                // the slot holds the last attempt's state, so that restore_nearest knows when it is the nearest
                slot = std::move(from_k_epsilon);
              }
          }
        catch (const std::runtime_error &)
          {
            if (!from_k_epsilon)
              failed.add_without_state("from k-epsilon's solution");
            else // model t diverged: from_k_epsilon holds k-epsilon's solution again
              {
                failed.add_diverged_start("from k-epsilon's solution", *from_k_epsilon);
                slot = std::move(from_k_epsilon);
              }
          }
      }
    // the nearest state is marched for the time average; its fields go to the case's VTU (a
    // later attempt, or k-epsilon's on the way to model t, wrote its own there)
    failed.restore_nearest(*slot);
    if (failed.has_state_to_march() && !failure_output.empty())
      slot->write_vtu(failure_output);
    failed.rethrow();
  }

  PilotFieldResult Chain::solve_from_rest(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp)
  {
    PilotFieldCase c = conditions;
    c.turbulence = t;
    slot = std::make_unique<PilotField>(settings, kind, c, h);
    slot->set_failure_output(failure_output);
    // the smaller steps for this solve only: the chain's next cases take the valve's
    slot->set_continuation_ratio(std::sqrt(settings.solution.continuation_ratio));
    try
      {
        PilotFieldResult r = slot->solve(dp);
        slot->set_continuation_ratio(settings.solution.continuation_ratio);
        return r;
      }
    catch (const std::runtime_error &)
      {
        slot->set_continuation_ratio(settings.solution.continuation_ratio);
        throw;
      }
  }

  PilotFieldResult Chain::solve_from_k_epsilon(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp)
  {
    PilotFieldCase c = conditions;
    c.turbulence = Turbulence::k_epsilon;
    auto k_epsilon = std::make_unique<PilotField>(settings, kind, c, h);
    k_epsilon->set_failure_output(failure_output);
    if (last && last_model == t)
      k_epsilon->set_fields(*last);
    const PilotFieldResult start = solve_with_retry(k_epsilon, Turbulence::k_epsilon, h, dp, true);
    c.turbulence = t;
    const auto start_model_t = [&] {
      slot = std::make_unique<PilotField>(settings, kind, c, h);
      slot->set_failure_output(failure_output);
      slot->set_fields(k_epsilon->fields());
    };
    start_model_t();
    try
      {
        PilotFieldResult r = slot->solve(dp);
        r.iterations += start.iterations + start.coarse_mesh_iterations;
        return r;
      }
    catch (const NotConverged &)
      {
        throw; // the stall is model t's state at the case's level
      }
    catch (const std::runtime_error &)
      {
        // diverged: model t set afresh into k-epsilon's solution, the state its time average may
        // march from (at 90 degC, Launder-Sharma's orifice at 15.45 MPa diverges in the steady
        // iteration from there but settles when marched; bench_orifice_march 90)
        start_model_t();
        throw;
      }
  }
} // namespace servodrift::flow
