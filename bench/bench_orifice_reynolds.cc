// Study driver (issue 5): RV-1's fixed orifice against the Lichtarowicz correlation E21 over
// Re_0 = 100 ... 2e4. The pressure difference stays at 10.3 MPa (40 degC, cavitation off: E21 is a
// single-phase correlation) and Re_0 is set by the viscosity, one case continuing from the last.
// Laminar below the stage's switch (`Pilot stage/Field solution/Fixed orifice transition Reynolds number', 1000),
// two-layer k-epsilon from it on; both models are run at the switch itself. Prints one row per case
// (data for scripts/orifice-reynolds, which plots doc/figures/orifice_lichtarowicz.*) with the
// iterations and wall time of each case.
//   OMP_THREAD_LIMIT=1 build/bench/bench_orifice_reynolds [parameter=value ...]
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "common/pilot_closed_forms.h"
#include "flow/pilot/pilot_field.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

int servodrift::bench::bench_orifice_reynolds(int argc, char **argv)
{
  std::vector<std::string> settings{"Output/Progress=none", "Pilot stage/Field solution/Cavitation=false"};
  for (int a = 1; a < argc; ++a)
    settings.emplace_back(argv[a]);
  const ValveDescription valve = load_valve_description("", settings);
  constexpr double T = 40, dp = 10.3e6;
  const PilotClosedForms closed_forms(valve, T);
  const PilotFieldCase at_T = pilot_field_case(valve, T);
  // Re_0 is inversely proportional to the viscosity at a fixed dp
  const double reynolds_at_T = closed_forms.fixed_orifice(dp).reynolds_number;
  const double length_over_diameter = valve.pilot.fixed_orifice_length / valve.pilot.fixed_orifice_diameter;
  const double switch_reynolds = valve.pilot.field_solution.fixed_orifice_transition_reynolds;
  using Turbulence = FlowSolverParameters::Turbulence;
  struct Point
  {
    double reynolds_number;
    Turbulence model;
  };
  std::vector<Point> points;
  for (double Re : {100.0, 200.0, 500.0})
    points.push_back({Re, Turbulence::laminar});
  points.push_back({switch_reynolds, Turbulence::laminar});
  for (double Re : {switch_reynolds, 2000.0, 5000.0, 10000.0, 20000.0})
    points.push_back({Re, Turbulence::k_epsilon});

  std::printf("# RV-1 fixed orifice, %g degC, dp %.1f MPa, no cavitation, Re_0 set by the viscosity\n", T, dp * 1e-6);
  std::printf("# Re_0[1] model(0 laminar, 1 k-epsilon) C_d[1] C_d_E21[1] deviation[%%] max_wall_y+[1] iterations[1] wall[s]\n");
  std::unique_ptr<PilotField> previous;
  for (const Point &point : points)
    {
      PilotFieldCase c = at_T;
      c.turbulence = point.model;
      c.fluid.viscosity = at_T.fluid.viscosity * reynolds_at_T / point.reynolds_number;
      auto orifice = std::make_unique<PilotField>(pilot_field_settings(valve), PilotGeometry::fixed_orifice, c);
      if (previous)
        orifice->initialize_from(*previous);
      const auto t0 = std::chrono::steady_clock::now();
      try
        {
          const PilotFieldResult r = orifice->solve(dp);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          const double e21 = lichtarowicz_discharge_coefficient(r.reynolds_number, length_over_diameter);
          std::printf("%8.0f %d %.5f %.5f %+6.2f %6.1f %6u %7.1f\n", r.reynolds_number, point.model == Turbulence::laminar ? 0 : 1,
                      r.discharge_coefficient, e21, 100 * (r.discharge_coefficient / e21 - 1), r.max_wall_y_plus, r.iterations,
                      seconds);
          previous = std::move(orifice);
        }
      catch (const std::exception &e)
        {
          std::printf("# Re_0 %.0f (%s): %s\n", point.reynolds_number, point.model == Turbulence::laminar ? "laminar" : "k-epsilon",
                      e.what());
        }
      std::fflush(stdout);
    }
  return 0;
}
