// Where a stalled hot orifice case is marched from (issue 28, item 6; doc/validation.md,
// "Robustness"): Launder-Sharma's cavitating orifice at 15.45 MPa, whose chain stalls far on every
// attempt and whose march from the nearest stall caps a sixth to a quarter of its steps
// (`bench_cold_start 30', `31'), marched instead from the two-layer k-epsilon's converged solution of
// the same case (k-epsilon's own chain: 1.03 MPa from rest, then 15.45 MPa), as the chain's time
// average would march it (flow/pilot_field_time_average.h: its plan, gate and statistics). Prints
// the k-epsilon solution, every capped step (C_d, its continuity, the cavitating cells and how many
// changed state within it, and the liquid cell of largest mass imbalance: where, its neighbours'
// state) and the time average. Not a test (minutes).
//   OMP_THREAD_LIMIT=1 build/bench/bench_orifice_march [T degC, default 100] [parameter=value ...]
#include "common/valve_description.h"
#include "flow/fv_mesh.h"
#include "flow/pilot_field.h"
#include "flow/pilot_field_cases.h"
#include "flow/pilot_field_time_average.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  /// The liquid cell of largest |net mixture outflow + mass change| (implicit Euler, the vapour's
  /// density neglected: a locator, not the solver's residual) and the sum over liquid cells, both
  /// relative to the inflow through the boundary.
  struct Imbalance
  {
    std::size_t cell = 0;
    double largest = 0, sum = 0;
  };

  Imbalance liquid_imbalance(const FvMesh &mesh, const FlowFields &now, const FlowFields &old, double dt)
  {
    std::vector<double> net(mesh.n_cells(), 0.0);
    double inflow = 0;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const double F = now.flux[f];
        const int o = mesh.owner[f], n = mesh.neighbour[f];
        if (n < 0 && F < 0)
          inflow -= F;
        const double m = n < 0 ? (F >= 0 ? now.liquid_fraction[o] : 1.0) : now.liquid_fraction[F >= 0 ? o : n];
        net[o] += m * F;
        if (n >= 0)
          net[n] -= m * F;
      }
    Imbalance worst;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        if (now.cavitating[c])
          continue;
        const double v = std::abs(net[c] + now.density * mesh.cell_volume[c] / dt * (1 - old.liquid_fraction[c])) / inflow;
        worst.sum += v;
        if (v > worst.largest)
          worst.largest = v, worst.cell = c;
      }
    return worst;
  }
} // namespace

int main(int argc, char **argv)
{
  const double T = argc > 1 ? std::atof(argv[1]) : 100;
  constexpr double dp = 15.45e6, start_dp = 1.03e6;
  std::vector<std::string> settings{"Output/Progress=none", "Output/Flow fields=none"};
  for (int a = 2; a < argc; ++a)
    settings.push_back(argv[a]);
  ValveDescription valve;
  try
    {
      valve = load_valve_description("", settings);
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "bench_orifice_march: %s\n", e.what());
      return 2;
    }
  if (!(T >= valve.fluid.minimum_temperature && T <= valve.fluid.maximum_temperature))
    {
      std::fprintf(stderr, "bench_orifice_march: temperature %g degC outside the fluid's range\n", T);
      return 2;
    }
  const auto t0 = std::chrono::steady_clock::now();
  valve.pilot.fixed_orifice_flow_model = PilotStageParameters::FlowModel::k_epsilon;
  Chain k_epsilon(valve, PilotGeometry::fixed_orifice, T);
  k_epsilon.solve(0, start_dp);
  const std::vector<double> r = k_epsilon.solve(0, dp);
  std::printf("two-layer k-epsilon at %g degC, %g MPa: flag %g, C_d %.5f\n", T, dp * 1e-6, r[case_record::flag],
              r[case_record::discharge_coefficient]);
  if (r[case_record::flag] != flags::computed && r[case_record::flag] != flags::beyond_verified || !k_epsilon.state())
    return 1;

  PilotFieldCase c = pilot_field_case(valve, T);
  c.turbulence = FlowSolverParameters::Turbulence::k_epsilon_launder_sharma;
  PilotField field(valve, PilotGeometry::fixed_orifice, c);
  field.set_fields(k_epsilon.state()->fields);
  FlowFields old = field.fields();
  if (old.liquid_fraction.empty()) // set before the cavitation model is on
    old.liquid_fraction.assign(field.n_cells(), 1.0), old.cavitating.assign(field.n_cells(), 0);
  const FvMesh &mesh = field.mesh();
  const TimeAverage a = time_average(field, dp, valve.pilot, [&](unsigned int step, unsigned int, double time,
                                                                 const PilotFieldResult &s) {
    FlowFields now = field.fields();
    if (!s.step_converged)
      {
        unsigned int cavitating = 0, changed = 0;
        for (std::size_t i = 0; i < now.cavitating.size(); ++i)
          cavitating += now.cavitating[i], changed += now.cavitating[i] != old.cavitating[i];
        const double dt = time / step;
        const Imbalance w = liquid_imbalance(mesh, now, old, dt);
        unsigned int neighbours = 0, cavitating_neighbours = 0;
        for (unsigned int f : mesh.cell_faces[w.cell])
          if (mesh.neighbour[f] >= 0)
            {
              const std::size_t other = mesh.owner[f] == w.cell ? mesh.neighbour[f] : mesh.owner[f];
              ++neighbours, cavitating_neighbours += now.cavitating[other];
            }
        std::printf("  step %u capped: C_d %.4f, continuity %.3g, %u cells cavitating (%u changed); liquid imbalance "
                    "%.3g, largest %.3g at x %.4g mm, r %.4g mm (old liquid fraction %.4f, %u of %u neighbours "
                    "cavitating)\n",
                    step, s.discharge_coefficient, s.step_residuals.continuity, cavitating, changed, w.sum, w.largest,
                    1e3 * mesh.cell_center[w.cell][0], 1e3 * mesh.cell_center[w.cell][1], old.liquid_fraction[w.cell],
                    cavitating_neighbours, neighbours);
      }
    else if (step % 250 == 0)
      std::printf("  step %u: C_d %.4f\n", step, s.discharge_coefficient);
    std::fflush(stdout);
    old = std::move(now);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("Launder-Sharma marched from it: C_d %.5f +- %.5f (spread %.5f), %u of %u averaged steps capped%s%s, "
              "decorrelation lag %u steps, %s; %.1f s\n",
              a.mean.discharge_coefficient, a.discharge_coefficient_uncertainty, a.discharge_coefficient_spread,
              a.unconverged_steps, a.averaged_steps, a.unconverged_steps ? ", held by " : "",
              capped_steps_held_by(a).c_str(), a.decorrelation_steps,
              steps_converged(a) && window_spans_motion(a) ? "the chain's gate passes it" : "the chain's gate refuses it",
              seconds);
}
