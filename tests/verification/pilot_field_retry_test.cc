// The retry ladder of the flow stage as data (flow/pilot/pilot_field_retry.h), against a scripted fake
// case: which attempts a case gets (retry_ladder), the one driver that runs them until one converges
// (run_ladder), and the ranking of the failed ones (FailedAttempts): the state nearest a steady state
// is the one its time average marches from, a stall at the case's level, else k-epsilon's solution
// that SST or Launder-Sharma diverged from, else a stall on the way. Why it matters: Launder-Sharma's
// orifice at 15.45 MPa and 100 degC, reached down the sweep's path, stalls far from steady
// (continuity 0.20) and its march caps 240 of 1 000 steps; the same case from a stall near steady
// (5e-3) averages calmly (doc/changes.md).
//
// Nothing is solved: each attempt's outcome is scripted, and its state is a field marked in its
// first cell's u (1, 2, 3, ...), so that which state the ranking keeps can be read back exactly.
// The whole file runs in milliseconds; the ladder's real paths are pilot_field_chain_test.cc's.
#include "flow/pilot/pilot_field_retry.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace servodrift::flow
{
  namespace
  {
    using Kind = AttemptOutcome::Kind;

    constexpr double case_level = 15.45e6; // [Pa]

    Residuals stall_at(double continuity) { return Residuals{1e-5, 1e-5, continuity, 1e-5, 1e-5}; }

    FlowFields marked(double marker)
    {
      FlowFields f;
      f.u = {marker};
      return f;
    }

    double marker_of(const FlowFields &f) { return f.u.empty() ? 0 : f.u.front(); }

    AttemptOutcome stalled(const std::string &message, double continuity, double level = case_level)
    {
      return {Kind::stalled, {}, message, stall_at(continuity), level};
    }

    AttemptOutcome diverged(const std::string &message = "diverged") { return {Kind::diverged, {}, message}; }

    /// Attempt `how' failed as `o' says, its state (if it left one) marked `marker'.
    void fail(FailedAttempts &attempts, const std::string &how, const AttemptOutcome &o, double marker = 0)
    {
      attempts.add(how, o, o.leaves_state() ? marked(marker) : FlowFields{});
    }

    /// A case whose attempts come to what the script says (converged where it says nothing), each
    /// leaving the state marked by the attempt's place in the ladder (1, 2, ...); it records the
    /// attempts in the order run and the states read.
    struct ScriptedCase
    {
      std::map<Attempt, AttemptOutcome> script;
      std::vector<Attempt> run;
      unsigned int states_read = 0;

      AttemptOutcome attempt(Attempt a)
      {
        run.push_back(a);
        const auto found = script.find(a);
        if (found != script.end())
          return found->second;
        AttemptOutcome o{Kind::converged};
        o.result.discharge_coefficient = 0.6;
        o.result.iterations = 100 * static_cast<unsigned int>(run.size());
        return o;
      }

      CaseOutcome solve(Turbulence t, bool own_state, FailedAttempts &failed)
      {
        const auto state_after = [&] {
          ++states_read;
          return marked(double(run.size()));
        };
        return run_ladder(
          retry_ladder(t, own_state), [&](Attempt a) { return attempt(a); }, state_after,
          [](Attempt a) { return name(a); }, failed);
      }

      static std::string name(Attempt a)
      {
        switch (a)
          {
            case Attempt::from_current_state: return "from the chain's last state";
            case Attempt::through_mean_level: return "through the mean level";
            case Attempt::from_rest_in_smaller_steps: return "from rest in smaller steps";
            case Attempt::from_k_epsilon_solution: return "from k-epsilon's solution";
          }
        return "";
      }
    };
  } // namespace

  // The ladder is a list: the case's current state; the chain's own state through the mean level
  // where it has one of the model at another level, else rest in smaller steps; and k-epsilon's
  // solution for the models less robust than it.
  TEST(PilotFieldRetry, TheLadderIsAListOfAttemptsPerModel)
  {
    using A = Attempt;
    EXPECT_EQ(retry_ladder(Turbulence::laminar, true), (std::vector<A>{A::from_current_state, A::through_mean_level}));
    EXPECT_EQ(retry_ladder(Turbulence::k_epsilon, false),
              (std::vector<A>{A::from_current_state, A::from_rest_in_smaller_steps}));
    for (const Turbulence t : {Turbulence::k_omega_sst, Turbulence::k_epsilon_launder_sharma})
      {
        EXPECT_EQ(retry_ladder(t, true),
                  (std::vector<A>{A::from_current_state, A::through_mean_level, A::from_k_epsilon_solution}));
        EXPECT_EQ(retry_ladder(t, false),
                  (std::vector<A>{A::from_current_state, A::from_rest_in_smaller_steps, A::from_k_epsilon_solution}));
      }
  }

  // The driver runs the attempts in order and stops at the first that converges, with its result;
  // a failure's state is read only where it left one; if none converges, the ranking's outcome.
  TEST(PilotFieldRetry, TheDriverRunsTheLadderUntilAnAttemptConverges)
  {
    ScriptedCase first;
    FailedAttempts none(case_level);
    const CaseOutcome at_once = first.solve(Turbulence::k_omega_sst, true, none);
    EXPECT_EQ(at_once.kind, CaseOutcome::Kind::converged);
    EXPECT_EQ(first.run, std::vector<Attempt>{Attempt::from_current_state});
    EXPECT_EQ(first.states_read, 0u);

    ScriptedCase sst; // SST's cavitating orifice: its own attempts fail, k-epsilon's solution carries it
    sst.script[Attempt::from_current_state] = diverged();
    sst.script[Attempt::through_mean_level] = stalled("stalled", 0.02, 10.3e6);
    FailedAttempts failed(case_level);
    const CaseOutcome from_k_epsilon = sst.solve(Turbulence::k_omega_sst, true, failed);
    EXPECT_EQ(from_k_epsilon.kind, CaseOutcome::Kind::converged);
    EXPECT_EQ(from_k_epsilon.result.iterations, 300u);
    EXPECT_EQ(sst.run, (std::vector<Attempt>{Attempt::from_current_state, Attempt::through_mean_level,
                                             Attempt::from_k_epsilon_solution}));
    EXPECT_EQ(sst.states_read, 1u); // the stall's; the divergence left none

    ScriptedCase laminar; // both attempts stall: the nearer one stands, at the case's level
    laminar.script[Attempt::from_current_state] = stalled("near", 5e-3);
    laminar.script[Attempt::from_rest_in_smaller_steps] = stalled("far", 0.2);
    FailedAttempts two(case_level);
    const CaseOutcome o = laminar.solve(Turbulence::laminar, false, two);
    EXPECT_EQ(laminar.run.size(), 2u);
    EXPECT_EQ(o.kind, CaseOutcome::Kind::stalled);
    EXPECT_EQ(o.residuals.continuity, 5e-3);
    EXPECT_EQ(marker_of(two.nearest_state()), 1);
    EXPECT_FALSE(two.last_is_nearest());
    EXPECT_EQ(o.message, "near (the stall nearest a steady state of 2 attempts: from the chain's last state stalled at "
                         "largest residual 0.005; from rest in smaller steps stalled at largest residual 0.2)");
  }

  // Five attempts: a far stall (0.2), a near one (5e-3), one that diverges, a stall between (0.05),
  // and the nearest by its residual (1e-3) on the way, at an intermediate pressure level, whose
  // residuals are of another problem. The near one at the case's level is kept, with its
  // residuals, its message naming every attempt in order with its outcome.
  TEST(PilotFieldRetry, TheStallNearestASteadyStateIsKeptWithTheListOfAttempts)
  {
    FailedAttempts attempts(case_level);
    fail(attempts, "from the chain's last state", stalled("far", 0.2), 1);
    fail(attempts, "from rest", stalled("near", 5e-3), 2);
    fail(attempts, "from k-epsilon's solution", diverged(), 3);
    fail(attempts, "from rest in smaller steps", stalled("between", 0.05), 4);
    fail(attempts, "from its own state", stalled("on the way", 1e-3, 7.3e6), 5);
    ASSERT_TRUE(attempts.has_state_to_march());
    EXPECT_FALSE(attempts.last_is_nearest());
    EXPECT_EQ(marker_of(attempts.nearest_state()), 2);
    const CaseOutcome o = attempts.outcome();
    EXPECT_EQ(o.kind, CaseOutcome::Kind::stalled);
    EXPECT_EQ(o.residuals.continuity, 5e-3);
    EXPECT_TRUE(o.residuals_known);
    EXPECT_EQ(o.level, case_level); // the level its residuals are of (flow/*_cases.csv)
    EXPECT_EQ(o.message.rfind("near (the stall nearest a steady state of 5 attempts: ", 0), 0u) << o.message;
    EXPECT_NE(o.message.find("from the chain's last state stalled at largest residual 0.2; from rest stalled at "
                             "largest residual 0.005; from k-epsilon's solution diverged; from rest in smaller steps "
                             "stalled at largest residual 0.05; from its own state stalled at largest residual 0.001 "
                             "on the way, at 7.3 MPa)"),
              std::string::npos)
      << o.message;
  }

  // The nearest stall is the last attempt: the case's field holds it already (the state marched
  // is the solver's own); a single attempt's stall keeps its message, without a list; an earlier
  // stall is the one to set back; with stalls on the way only, the nearest of those.
  TEST(PilotFieldRetry, ALastNearestStallStaysAndASingleStallKeepsItsMessage)
  {
    FailedAttempts one(case_level);
    fail(one, "from rest", stalled("alone", 0.1), 1);
    EXPECT_TRUE(one.last_is_nearest());
    EXPECT_EQ(one.outcome().message, "alone");
    EXPECT_EQ(one.outcome().residuals.continuity, 0.1);

    FailedAttempts two(case_level);
    fail(two, "from the chain's last state", stalled("far", 0.2), 1);
    fail(two, "from rest", stalled("near", 5e-3), 2);
    EXPECT_TRUE(two.last_is_nearest());
    EXPECT_EQ(marker_of(two.nearest_state()), 2);

    FailedAttempts three(case_level);
    fail(three, "from rest", stalled("near", 5e-3), 1);
    fail(three, "from rest in smaller steps", stalled("far", 0.2), 2);
    fail(three, "from k-epsilon's solution", stalled("farther", 0.3), 3);
    EXPECT_FALSE(three.last_is_nearest());
    EXPECT_EQ(marker_of(three.nearest_state()), 1);

    // stalls on the way only: the nearest of them stands
    FailedAttempts on_the_way(case_level);
    fail(on_the_way, "from the chain's last state", stalled("farther", 0.3, 5.15e6), 1);
    fail(on_the_way, "from rest", stalled("far", 0.1, 10.3e6), 2);
    fail(on_the_way, "from k-epsilon's solution", diverged(), 3);
    EXPECT_FALSE(on_the_way.last_is_nearest());
    EXPECT_EQ(marker_of(on_the_way.nearest_state()), 2);
    EXPECT_EQ(on_the_way.outcome().level, 10.3e6); // its residuals are of that level's problem
    EXPECT_EQ(on_the_way.outcome().residuals.continuity, 0.1);
  }

  // No attempt left a state (every one diverged, or k-epsilon's solve failed): the case comes to
  // what the last attempt came to, with its message: failed, or stalled where k-epsilon's solve
  // stalled (its time average then marches the case's field as it is).
  TEST(PilotFieldRetry, WithoutAStateTheLastFailureStands)
  {
    FailedAttempts attempts(case_level);
    fail(attempts, "from the chain's last state", diverged("diverged first"));
    fail(attempts, "from k-epsilon's solution", AttemptOutcome{Kind::failed_without_state, {}, "k-epsilon failed"});
    EXPECT_FALSE(attempts.has_state_to_march());
    const CaseOutcome o = attempts.outcome();
    EXPECT_EQ(o.kind, CaseOutcome::Kind::failed);
    EXPECT_EQ(o.message, "k-epsilon failed");

    FailedAttempts stall(case_level);
    fail(stall, "from the chain's last state", diverged());
    AttemptOutcome k_epsilon_stalled{Kind::failed_without_state, {}, "k-epsilon stalled", stall_at(0.3), 7.3e6};
    k_epsilon_stalled.k_epsilon_stalled = true;
    fail(stall, "from k-epsilon's solution", k_epsilon_stalled);
    EXPECT_FALSE(stall.has_state_to_march());
    EXPECT_EQ(stall.outcome().kind, CaseOutcome::Kind::stalled);
    EXPECT_EQ(stall.outcome().message, "k-epsilon stalled");
    EXPECT_TRUE(stall.outcome().residuals_known); // k-epsilon's stall's, the state its VTU holds
    EXPECT_TRUE(stall.outcome().k_epsilon_state);
    EXPECT_EQ(stall.outcome().level, 7.3e6);
    EXPECT_FALSE(o.residuals_known);
    EXPECT_FALSE(o.k_epsilon_state);
  }

  // Launder-Sharma's orifice at 90 degC down the sweep's path: its own attempts stall on the way
  // (at 6.26 MPa, whose march diverged at its first step) and it diverges from k-epsilon's
  // solution, from which it settles when marched (bench_orifice_march 90). That start is the state
  // to march, ahead of stalls on the way but behind a stall at the case's level (the model's own
  // state); the case comes to a stall (so that the chain marches it) at the case's level with
  // residuals not known (zero), since model t's are not known there, even when it is the only attempt.
  TEST(PilotFieldRetry, AStartThatDivergedRanksBetweenStallsAtTheCaseLevelAndOnTheWay)
  {
    const AttemptOutcome start{Kind::diverged_from_start, {}, "diverged"};
    FailedAttempts on_the_way(case_level);
    fail(on_the_way, "from the chain's last state", stalled("far", 0.49, 6.26e6), 1);
    fail(on_the_way, "from rest in smaller steps", stalled("farther", 1.1, 7.73e6), 2);
    fail(on_the_way, "from k-epsilon's solution", start, 3);
    ASSERT_TRUE(on_the_way.has_state_to_march());
    EXPECT_TRUE(on_the_way.last_is_nearest());
    EXPECT_EQ(marker_of(on_the_way.nearest_state()), 3);
    const CaseOutcome marched = on_the_way.outcome();
    EXPECT_EQ(marched.kind, CaseOutcome::Kind::stalled);
    EXPECT_EQ(largest_residual(marched.residuals), 0);
    EXPECT_FALSE(marched.residuals_known);
    EXPECT_EQ(marched.level, case_level);
    EXPECT_EQ(marched.message, "diverged (its start from k-epsilon's solution, the state nearest a steady state of 3 "
                               "attempts: from the chain's last state stalled at largest residual 0.49 on the way, at "
                               "6.26 MPa; from rest in smaller steps stalled at largest residual 1.1 on the way, at "
                               "7.73 MPa; from k-epsilon's solution diverged)");

    FailedAttempts at_level(case_level);
    fail(at_level, "from rest", stalled("own", 0.2), 1);
    fail(at_level, "from k-epsilon's solution", start, 3);
    EXPECT_FALSE(at_level.last_is_nearest());
    EXPECT_EQ(marker_of(at_level.nearest_state()), 1);
    EXPECT_EQ(at_level.outcome().residuals.continuity, 0.2);
    EXPECT_TRUE(at_level.outcome().residuals_known);

    FailedAttempts alone(case_level);
    fail(alone, "from k-epsilon's solution", start, 4);
    EXPECT_EQ(alone.outcome().message, "diverged (its start from k-epsilon's solution, the state nearest a steady state "
                                       "of 1 attempt: from k-epsilon's solution diverged)");
  }
} // namespace servodrift::flow
