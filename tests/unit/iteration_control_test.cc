// The flow solver's iteration control (flow/fv/iteration_control.h) on synthetic residual histories:
// each test feeds the residuals a run would have and checks the verdict, the iteration it comes at,
// the pressure relaxation, the switch to coupled iterations and the Anderson phases, against the
// rules of the header (tolerance, divergence, monitors, cycle and stall windows, iteration limit).
#include "common/valve_description.h"
#include "flow/fv/iteration_control.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

using namespace servodrift;
using namespace servodrift::flow;
using Verdict = IterationControl::Verdict;

namespace
{
  /// The default `Flow solver' subsection with the windows of a test: no acceleration unless asked.
  FlowSolverParameters settings(unsigned int stall_window, unsigned int cycle_window,
                                FlowSolverParameters::Coupling coupling = FlowSolverParameters::Coupling::simplec)
  {
    FlowSolverParameters s = load_valve_description("", {"Output/Progress=none"}).flow_solver;
    s.stall_window = stall_window;
    s.cycle_window = cycle_window;
    s.coupling = coupling;
    s.acceleration_depth = 0;
    s.max_iterations = 100000;
    s.pressure_relaxation = 0.7;
    return s;
  }

  Residuals all(double value) { return {value, value, value, 0, 0}; }

  /// A state that Anderson acceleration never sees (the tests without it).
  struct NoState : AcceleratedState
  {
    Eigen::VectorXd pack() override
    {
      ADD_FAILURE() << "pack without acceleration";
      return {};
    }
    void unpack(const Eigen::VectorXd &) override { ADD_FAILURE() << "unpack without acceleration"; }
    void forget_scales() override { ++forgotten; }
    int forgotten = 0;
  };

  /// Feeds residual(it) until the verdict is not go_on or `limit' iterations; the final verdict.
  Verdict run(IterationControl &control, AcceleratedState &state, const std::function<Residuals(unsigned int)> &residual,
              unsigned int limit = 100000)
  {
    for (unsigned int i = 0; i < limit; ++i)
      {
        const unsigned int it = control.next();
        const Verdict v = control.judge(residual(it), state);
        if (v != Verdict::go_on)
          return v;
      }
    return Verdict::go_on;
  }
} // namespace

TEST(IterationControl, ConvergesAtTheFirstIterationBelowTheTolerance)
{
  IterationControl control(settings(1000, 200), 1e-6, nullptr, false);
  NoState state;
  // residuals falling tenfold per 10 iterations from 1: below 1e-6 from iteration 61
  EXPECT_EQ(run(control, state, [](unsigned int it) { return all(std::pow(10.0, -double(it) / 10)); }), Verdict::converged);
  EXPECT_EQ(control.iteration(), 61u);
  // every residual counts, k and epsilon too
  IterationControl turbulent(settings(1000, 200), 1e-6, nullptr, true);
  EXPECT_EQ(run(turbulent, state,
                [](unsigned int it) { return Residuals{1e-7, 1e-7, 1e-7, it < 30 ? 1e-3 : 1e-7, 1e-7}; }),
            Verdict::converged);
  EXPECT_EQ(turbulent.iteration(), 30u);
}

TEST(IterationControl, MonitoredQuantitiesMustSettleOverTheirWindow)
{
  // residuals below the tolerance from the start; the monitored value moves by 1e-3 per iteration
  // until iteration 100, then stays: settled once the window of 20 (21 samples) holds only the
  // constant value, at iteration 120
  unsigned int calls = 0;
  ConvergenceMonitor monitor{[&] {
                               ++calls;
                               return std::vector<double>{1.0 + 1e-3 * std::min(calls, 100u)};
                             },
                             20, 1e-4};
  IterationControl control(settings(1000, 200), 1e-6, &monitor, false);
  NoState state;
  EXPECT_EQ(run(control, state, [](unsigned int) { return all(1e-9); }), Verdict::converged);
  EXPECT_EQ(control.iteration(), 120u);
  EXPECT_EQ(calls, 120u); // sampled every iteration

  // a change within the relative tolerance does not hold it back: settled after the first window
  calls = 0;
  ConvergenceMonitor quiet{[&] { return std::vector<double>{1.0 + 1e-6 * ++calls}; }, 20, 1e-4};
  IterationControl settled(settings(1000, 200), 1e-6, &quiet, false);
  EXPECT_EQ(run(settled, state, [](unsigned int) { return all(1e-9); }), Verdict::converged);
  EXPECT_EQ(settled.iteration(), 21u);
}

TEST(IterationControl, DivergenceStopsTheRun)
{
  NoState state;
  // a NaN at once
  IterationControl nan(settings(1000, 200), 1e-6, nullptr, false);
  EXPECT_EQ(run(nan, state,
                [](unsigned int it) { return it == 7 ? Residuals{1, std::nan(""), 1, 0, 0} : all(1); }),
            Verdict::diverged);
  EXPECT_EQ(nan.iteration(), 7u);
  EXPECT_NE(nan.reason().find("diverged at iteration 7"), std::string::npos) << nan.reason();
  // huge residuals are allowed during the first 10 iterations (a start from rest), not after
  IterationControl huge(settings(1000, 200), 1e-6, nullptr, false);
  EXPECT_EQ(run(huge, state, [](unsigned int) { return all(1e9); }), Verdict::diverged);
  EXPECT_EQ(huge.iteration(), IterationControl::divergence_grace + 1);
}

TEST(IterationControl, IterationLimit)
{
  FlowSolverParameters s = settings(0, 0);
  s.max_iterations = 37;
  IterationControl control(s, 1e-6, nullptr, true);
  NoState state;
  EXPECT_EQ(run(control, state, [](unsigned int) { return Residuals{1e-3, 2e-3, 3e-3, 4e-3, 5e-3}; }),
            Verdict::not_converged);
  EXPECT_EQ(control.iteration(), 37u);
  EXPECT_NE(control.reason().find("not converged in 37 iterations (residuals u 0.001, v 0.002, k 0.004, epsilon 0.005, continuity 0.003; tolerance 1e-06)"),
            std::string::npos)
    << control.reason();
}

TEST(IterationControl, CycleTestLowersThePressureRelaxationToItsFloor)
{
  // a flat residual: no window halves the last one's best. The first window has no predecessor;
  // each lowering judges the next window afresh, so the relaxation falls every second window:
  // 0.7 -> 0.49 (iteration 100) -> 0.343 (200) -> 0.3 (300, the floor), and stays
  IterationControl control(settings(0, 50), 1e-6, nullptr, false);
  NoState state;
  std::vector<std::pair<unsigned int, double>> lowered;
  for (unsigned int i = 0; i < 500; ++i)
    {
      const unsigned int it = control.next();
      ASSERT_EQ(control.judge(all(1e-2), state), Verdict::go_on);
      if (control.relaxation_lowered())
        lowered.emplace_back(it, control.pressure_relaxation());
    }
  ASSERT_EQ(lowered.size(), 3u);
  EXPECT_EQ(lowered[0].first, 100u);
  EXPECT_DOUBLE_EQ(lowered[0].second, 0.49);
  EXPECT_EQ(lowered[1].first, 200u);
  EXPECT_DOUBLE_EQ(lowered[1].second, 0.343);
  EXPECT_EQ(lowered[2].first, 300u);
  EXPECT_DOUBLE_EQ(lowered[2].second, IterationControl::lowest_pressure_relaxation);
  EXPECT_DOUBLE_EQ(control.coupled_pressure_relaxation(), 0.3 / 0.7);

  // a residual that halves every window is a convergence, not a cycle
  IterationControl converging(settings(0, 50), 1e-12, nullptr, false);
  EXPECT_EQ(run(converging, state, [](unsigned int it) { return all(std::pow(0.5, it / 49.0)); }, 1000),
            Verdict::go_on);
  EXPECT_DOUBLE_EQ(converging.pressure_relaxation(), 0.7);
}

TEST(IterationControl, StalledSimplecFailsOrGoesOnCoupled)
{
  NoState state;
  // SIMPLEC only: a plateau from iteration 1 stalls at the end of the second window
  IterationControl simplec(settings(100, 0), 1e-6, nullptr, false);
  EXPECT_EQ(run(simplec, state, [](unsigned int) { return all(1e-2); }), Verdict::not_converged);
  EXPECT_EQ(simplec.iteration(), 200u);
  EXPECT_NE(simplec.reason().find("not converged in 200 iterations: stalled"), std::string::npos) << simplec.reason();

  // simplec-then-coupled: the stall switches to coupled iterations with the setting's relaxation,
  // judged on the cycle window from there against SIMPLEC's best
  IterationControl switching(settings(100, 30, FlowSolverParameters::Coupling::simplec_then_coupled), 1e-6, nullptr,
                             false);
  EXPECT_FALSE(switching.coupled());
  unsigned int switched_at = 0, back_at = 0;
  bool coupled_at_switch = false;
  double relaxation_at_switch = 0;
  Verdict v = Verdict::go_on;
  while (v == Verdict::go_on)
    {
      const unsigned int it = switching.next();
      v = switching.judge(all(1e-2), state);
      if (switching.switched_to_coupled())
        switched_at = it, coupled_at_switch = switching.coupled(), relaxation_at_switch = switching.pressure_relaxation();
      if (switching.switched_back_to_simplec())
        back_at = it;
    }
  EXPECT_EQ(switched_at, 200u);
  EXPECT_TRUE(coupled_at_switch);
  EXPECT_DOUBLE_EQ(relaxation_at_switch, 0.7);
  // the coupled iterations do not halve SIMPLEC's plateau within their first cycle window: SIMPLEC
  // again, once, judged on 4 stall windows (400) with the first one free. The cycle test lowers the
  // relaxation at 270, 330 and 390 (to its floor; a lowering judges the next cycle window afresh),
  // each lowering a new window's start: 391-790 free, 791-1190 not halving it
  EXPECT_EQ(back_at, 230u);
  EXPECT_FALSE(switching.coupled());
  EXPECT_EQ(v, Verdict::not_converged);
  EXPECT_EQ(switching.iteration(), 1190u);
  EXPECT_NE(switching.reason().find("coupled iterations since SIMPLEC stalled at iteration 200, SIMPLEC again since "
                                    "they stalled at iteration 230"),
            std::string::npos)
    << switching.reason();

  // coupled iterations that converge after the switch
  IterationControl resolving(settings(100, 30, FlowSolverParameters::Coupling::simplec_then_coupled), 1e-6, nullptr,
                             false);
  EXPECT_EQ(run(resolving, state,
                [](unsigned int it) { return all(it <= 200 ? 1e-2 : 1e-2 * std::pow(0.5, it - 200.0)); }),
            Verdict::converged);
  EXPECT_TRUE(resolving.coupled());
  EXPECT_EQ(resolving.iteration(), 214u); // 1e-2 / 2^14 < 1e-6

  // a start state's solve (resume_simplec false: an intermediate level, a check) fails there instead
  IterationControl start_state(settings(100, 30, FlowSolverParameters::Coupling::simplec_then_coupled), 1e-6, nullptr,
                               false, false);
  EXPECT_EQ(run(start_state, state, [](unsigned int) { return all(1e-2); }), Verdict::not_converged);
  EXPECT_TRUE(start_state.coupled());
  EXPECT_EQ(start_state.iteration(), 230u);
  EXPECT_NE(start_state.reason().find("coupled iterations since SIMPLEC stalled at iteration 200)"), std::string::npos)
    << start_state.reason();

  // and SIMPLEC's slow convergence from there converges: flat to 500, then a tenth every 400
  // iterations (each 400-window halving the last, not each 100-window)
  IterationControl slow(settings(100, 30, FlowSolverParameters::Coupling::simplec_then_coupled), 1e-6, nullptr, false);
  EXPECT_EQ(run(slow, state, [](unsigned int it) { return all(it <= 500 ? 2e-2 : 2e-2 * std::pow(0.1, (it - 500.0) / 400)); }),
            Verdict::converged);
  EXPECT_FALSE(slow.coupled());
  EXPECT_EQ(slow.iteration(), 2221u); // 2e-2 * 0.1^(1721/400) < 1e-6

  // `coupled' from the start never switches
  IterationControl coupled(settings(100, 30, FlowSolverParameters::Coupling::coupled), 1e-6, nullptr, false);
  EXPECT_TRUE(coupled.coupled());
  EXPECT_EQ(run(coupled, state, [](unsigned int) { return all(1e-2); }), Verdict::not_converged);
  EXPECT_EQ(coupled.iteration(), 200u);
}

TEST(IterationControl, CoupledStallTestGivesALoweredRelaxationAWholeWindow)
{
  // SIMPLEC flat at 1e-2 stalls at 200 (stall window 100); the coupled iterations fall to 1e-3 and
  // hover: their first window (201-230) halves SIMPLEC's best, the cycle test lowers the relaxation
  // at 240 (211-240 did not halve 201-210). The stall test's next window then runs 241-270 under the
  // new setting alone, instead of 231-260 of which the old one ran 10 iterations
  NoState state;
  const auto s = settings(100, 30, FlowSolverParameters::Coupling::simplec_then_coupled);
  auto hover_then_converge = [](unsigned int it) {
    return all(it <= 200 ? 1e-2 : it <= 265 ? 1e-3 : 1e-3 * std::pow(0.5, it - 265.0));
  };
  IterationControl converging(s, 1e-6, nullptr, false);
  unsigned int lowered_at = 0;
  Verdict v = Verdict::go_on;
  while (v == Verdict::go_on)
    {
      const unsigned int it = converging.next();
      v = converging.judge(hover_then_converge(it), state);
      if (converging.relaxation_lowered())
        lowered_at = it;
    }
  EXPECT_EQ(lowered_at, 240u);
  EXPECT_EQ(v, Verdict::converged); // judged at 260 with the old windows, it stalled there
  EXPECT_EQ(converging.iteration(), 275u); // 1e-3 / 2^10 < 1e-6

  // a hover that the lowered relaxation does not end still stalls the coupled iterations, one whole
  // window after it (270); SIMPLEC again from there lowers the relaxation at 330 and 390 (0.49 since
  // 240) and stalls at 1190, 391-790 free and 791-1190 not halving it
  IterationControl hovering(s, 1e-6, nullptr, false);
  unsigned int back_at = 0;
  v = Verdict::go_on;
  while (v == Verdict::go_on)
    {
      const unsigned int it = hovering.next();
      v = hovering.judge(all(it <= 200 ? 1e-2 : 1e-3), state);
      if (hovering.switched_back_to_simplec())
        back_at = it;
    }
  EXPECT_EQ(back_at, 270u);
  EXPECT_EQ(v, Verdict::not_converged);
  EXPECT_EQ(hovering.iteration(), 1190u);
  EXPECT_NE(hovering.reason().find("stalled"), std::string::npos) << hovering.reason();
}

TEST(IterationControl, CoupledHoverNearTheToleranceHoldsTheLimiters)
{
  // coupled iterations hovering at 3e-6 (tolerance 1e-6, within the 10 tolerances): the first caught
  // cycle (iteration 60, cycle window 30) holds the limiters, once, and lowers the relaxation
  NoState state;
  auto s = settings(0, 30, FlowSolverParameters::Coupling::coupled);
  IterationControl near(s, 1e-6, nullptr, false);
  unsigned int held_at = 0, starts = 0;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const unsigned int it = near.next();
      ASSERT_EQ(near.judge(all(3e-6), state), Verdict::go_on);
      if (near.limiters_hold_started())
        held_at = it, ++starts;
      if (it < 60)
        {
          EXPECT_FALSE(near.limiters_held_now()) << it;
        }
    }
  EXPECT_EQ(held_at, 60u);
  EXPECT_EQ(starts, 1u);
  EXPECT_TRUE(near.limiters_held_now());
  EXPECT_DOUBLE_EQ(near.pressure_relaxation(), IterationControl::lowest_pressure_relaxation); // 60, 120, 180

  // the same hover far above the tolerance (1e-3): the relaxation falls, the limiters stay free
  IterationControl far(s, 1e-6, nullptr, false);
  EXPECT_EQ(run(far, state, [](unsigned int) { return all(1e-3); }, 200), Verdict::go_on);
  EXPECT_FALSE(far.limiters_held_now());
  EXPECT_DOUBLE_EQ(far.pressure_relaxation(), IterationControl::lowest_pressure_relaxation);

  // SIMPLEC's cycles never hold them, however close to the tolerance
  IterationControl simplec(settings(0, 30), 1e-6, nullptr, false);
  EXPECT_EQ(run(simplec, state, [](unsigned int) { return all(3e-6); }, 200), Verdict::go_on);
  EXPECT_FALSE(simplec.limiters_held_now());
}

namespace
{
  /// The outer iteration as a linear contraction x <- M x + b (eigenvalues spread over [0, 0.98]),
  /// with the state Anderson acceleration packs and writes back; residual = |G(x) - x| / |b|.
  struct LinearIteration : AcceleratedState
  {
    Eigen::MatrixXd M;
    Eigen::VectorXd b, x;
    int packs = 0, unpacks = 0, forgotten = 0;
    explicit LinearIteration(int n)
      : x(Eigen::VectorXd::Zero(n))
    {
      Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
      Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(n, 0, 0.98);
      M = Q * lambda.asDiagonal() * Q.transpose();
      b = Eigen::VectorXd::LinSpaced(n, -1, 1);
    }
    double step() // one plain iteration; its residual
    {
      const Eigen::VectorXd next = M * x + b;
      const double r = (next - x).norm() / b.norm();
      x = next;
      return r;
    }
    Eigen::VectorXd pack() override { return ++packs, x; }
    void unpack(const Eigen::VectorXd &y) override { ++unpacks, x = y; }
    void forget_scales() override { ++forgotten; }
  };

  /// Iterations to convergence; in `below_start' those judged below the acceleration start.
  unsigned int iterations(LinearIteration &G, FlowSolverParameters s, int &below_start)
  {
    IterationControl control(s, 1e-10, nullptr, false);
    Verdict v = Verdict::go_on;
    below_start = 0;
    while (v == Verdict::go_on)
      {
        control.next();
        const double r = G.step();
        v = control.judge(all(r), G);
        below_start += v == Verdict::go_on && r < s.acceleration_start;
      }
    EXPECT_EQ(v, Verdict::converged);
    return control.iteration();
  }
} // namespace

TEST(IterationControl, AndersonAccelerationFromItsStartOnwards)
{
  FlowSolverParameters s = settings(0, 0);
  LinearIteration plain(30);
  LinearIteration accelerated = plain; // the same map
  int below = 0;
  const unsigned int n_plain = iterations(plain, s, below);
  EXPECT_EQ(plain.packs, 0);
  s.acceleration_depth = 10;
  s.acceleration_start = 1e-2;
  const unsigned int n_accelerated = iterations(accelerated, s, below);
  std::printf("plain %u iterations, accelerated %u (%d below the start; packs %d, unpacks %d)\n", n_plain,
              n_accelerated, below, accelerated.packs, accelerated.unpacks);
  // GMRES-like: far fewer iterations, the same fixed point
  EXPECT_LT(n_accelerated, n_plain / 4);
  EXPECT_LT((accelerated.x - plain.x).norm(), 1e-8 * plain.x.norm());
  // only below the start, every iteration there; the first pack records where the phase starts
  EXPECT_EQ(accelerated.packs, below);
  EXPECT_EQ(accelerated.unpacks, accelerated.packs - 1);
}

TEST(IterationControl, AccelerationStopsAboveItsStartAndAtACycle)
{
  FlowSolverParameters s = settings(0, 20);
  s.acceleration_depth = 5;
  s.acceleration_start = 1e-2;
  LinearIteration G(10);
  IterationControl control(s, 1e-12, nullptr, false);
  // below the start for 10 iterations (accelerated), then above it: the phase ends, the scales are
  // forgotten once
  for (int i = 0; i < 10; ++i)
    {
      control.next();
      G.step();
      ASSERT_EQ(control.judge(all(1e-3), G), Verdict::go_on);
    }
  EXPECT_EQ(G.packs, 10);
  EXPECT_EQ(G.unpacks, 9);
  EXPECT_EQ(G.forgotten, 0);
  control.next();
  G.step();
  ASSERT_EQ(control.judge(all(1e-1), G), Verdict::go_on);
  EXPECT_EQ(G.forgotten, 1);
  EXPECT_EQ(G.packs, 10);
  // a cycle caught (iteration 40: the second flat window) ends it too: another iteration map
  for (unsigned int it = control.iteration() + 1; it <= 40; ++it)
    {
      control.next();
      G.step();
      ASSERT_EQ(control.judge(all(1e-3), G), Verdict::go_on);
    }
  EXPECT_TRUE(control.relaxation_lowered());
  EXPECT_EQ(G.forgotten, 2);
}

TEST(IterationControl, AccelerationRestartsWhenTheChangeGrowsTenfold)
{
  FlowSolverParameters s = settings(0, 0);
  s.acceleration_depth = 5;
  s.acceleration_start = 1;
  // a state whose packed value jumps: the change G(x) - x grows a hundredfold at the fourth pack,
  // so that combination is not written back and the history starts again from it
  struct Jumping : AcceleratedState
  {
    int packs = 0, unpacks = 0;
    Eigen::VectorXd pack() override
    {
      ++packs;
      Eigen::VectorXd g = Eigen::VectorXd::Constant(3, 1.0 + 1e-3 * packs);
      if (packs == 4)
        g *= 1.5;
      return g;
    }
    void unpack(const Eigen::VectorXd &) override { ++unpacks; }
    void forget_scales() override {}
  } state;
  IterationControl control(s, 1e-12, nullptr, false);
  for (int i = 0; i < 6; ++i)
    {
      control.next();
      ASSERT_EQ(control.judge(all(1e-3), state), Verdict::go_on);
    }
  EXPECT_EQ(state.packs, 6);
  EXPECT_EQ(state.unpacks, 4); // packs 2, 3, 5, 6: the first records the start, the fourth restarts
}

TEST(IterationControl, ProgressReportInterval)
{
  FlowSolverParameters s = settings(0, 0);
  s.report_interval = 25;
  IterationControl control(s, 1e-6, nullptr, false);
  NoState state;
  unsigned int due = 0;
  for (int i = 0; i < 100; ++i)
    {
      control.next();
      control.judge(all(1), state);
      due += control.report_due();
    }
  EXPECT_EQ(due, 4u);
}
