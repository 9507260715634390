// Where a stalled hot orifice case is marched from (issue 28, item 6; doc/validation.md,
// "Robustness"): Launder-Sharma's cavitating orifice at 15.45 MPa, whose chain stalls far on every
// attempt and whose march from the nearest stall caps a sixth to a quarter of its steps
// (`bench_cold_start 30', `31'), marched instead from the two-layer k-epsilon's converged solution of
// the same case (k-epsilon's own chain: 1.03 MPa from rest, then 15.45 MPa), as the chain's time
// average would march it (flow/pilot/pilot_field_time_average.h: its plan, gate and statistics). Prints
// the k-epsilon solution, every capped step (C_d, its continuity, the cavitating cells and how many
// changed state within it, and the liquid cell of largest mass imbalance by the solver's own
// measure: where, its neighbours' state) and the time average. Not a test (minutes).
//   OMP_THREAD_LIMIT=1 build/bench/bench_orifice_march [T degC, default 100] [parameter=value ...]
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/fv/cavitation_model.h"
#include "flow/fv/continuity.h"
#include "flow/fv/fv_mesh.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_cases.h"
#include "flow/pilot/pilot_field_time_average.h"

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
  /// The liquid cell of largest mass imbalance and the sum over liquid cells, relative to the
  /// throughput: the solver's own measures (flow/fv/continuity.h) of the step's fields, its time
  /// derivative taken as implicit Euler from the previous step's liquid fractions (a locator: the
  /// solver's BDF2 weights after its first step differ).
  struct Imbalance
  {
    std::size_t cell = 0;
    double largest = 0, sum = 0;
  };

  Imbalance liquid_imbalance(const FvMesh &mesh, double vapour_density_ratio, const FlowFields &now,
                             const FlowFields &old, double dt)
  {
    CavitationModel cavitation(mesh, vapour_density_ratio);
    cavitation.enable(0); // the floor is not used by the imbalance
    cavitation.gamma = old.liquid_fraction;
    TimeLevel time;
    time.dt = dt;
    time.last.mixture = cavitation.mixture_ratios();
    cavitation.gamma = now.liquid_fraction, cavitation.cavitating = now.cavitating;
    const std::vector<double> imbalance = cell_mass_imbalance(mesh, now.flux, cavitation, &time, now.density);
    const double throughput = continuity_reference(mesh, now.flux, 0);
    Imbalance worst;
    worst.sum = liquid_imbalance_sum(imbalance, cavitation) / throughput;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      if (!cavitation.cell_cavitates(c) && std::abs(imbalance[c]) / throughput > worst.largest)
        worst.largest = std::abs(imbalance[c]) / throughput, worst.cell = c;
    return worst;
  }
} // namespace

int servodrift::bench::bench_orifice_march(int argc, char **argv)
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
  valve.pilot.field_solution.fixed_orifice_flow_model = PilotFieldSolutionParameters::FlowModel::k_epsilon;
  Chain k_epsilon(valve, PilotGeometry::fixed_orifice, T);
  k_epsilon.solve(0, start_dp);
  const std::vector<double> r = k_epsilon.solve(0, dp);
  std::printf("two-layer k-epsilon at %g degC, %g MPa: flag %g, C_d %.5f\n", T, dp * 1e-6, r[case_record::flag],
              r[case_record::discharge_coefficient]);
  if ((r[case_record::flag] != flags::computed && r[case_record::flag] != flags::beyond_verified) || !k_epsilon.state())
    return 1;

  PilotFieldCase c = pilot_field_case(valve, T);
  c.turbulence = FlowSolverParameters::Turbulence::k_epsilon_launder_sharma;
  PilotField field(pilot_field_settings(valve), PilotGeometry::fixed_orifice, c);
  field.set_fields(k_epsilon.state()->fields);
  FlowFields old = field.fields();
  if (old.liquid_fraction.empty()) // set before the cavitation model is on
    old.liquid_fraction.assign(field.n_cells(), 1.0), old.cavitating.assign(field.n_cells(), 0);
  const FvMesh &mesh = field.mesh();
  const TimeAverage a = time_average(field, dp, valve.pilot.time_average, [&](unsigned int step, unsigned int, double time,
                                                                 const PilotFieldResult &s) {
    FlowFields now = field.fields();
    if (!s.step_converged)
      {
        unsigned int cavitating = 0, changed = 0;
        for (std::size_t i = 0; i < now.cavitating.size(); ++i)
          cavitating += now.cavitating[i], changed += now.cavitating[i] != old.cavitating[i];
        const double dt = time / step;
        const Imbalance w = liquid_imbalance(mesh, valve.flow_solver.vapour_density_ratio, now, old, dt);
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
                    step, s.discharge_coefficient, s.residuals.continuity, cavitating, changed, w.sum, w.largest,
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
  return 0;
}
