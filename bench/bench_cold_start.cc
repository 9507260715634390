// Robustness of single field-level pilot cases started from rest (issue 28, item 6): the cases the
// issue lists as failing, each solved alone from rest at 40 degC on RV-1 (no continuation from a
// neighbouring case), with every flow model. Prints per case the outcome (converged, or the
// solver's reason), the iterations, the wall time, C_d and the flapper force. Not a test (minutes).
//   OMP_THREAD_LIMIT=1 build/bench/bench_cold_start [case numbers, default all, e.g. 1,4,7]
#include "common/valve_description.h"
#include "flow/pilot_field.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;
using Turbulence = FlowSolverParameters::Turbulence;

namespace
{
  struct ColdStart
  {
    const char *what;
    PilotGeometry geometry;
    Turbulence model;
    double resolution;
    double gap;               ///< [m] (nozzle)
    double pressure_difference; ///< [Pa]
    bool cavitation;
    double realizability; ///< Flow solver/Realizability coefficient (0: off)
  };

  const char *name(Turbulence t)
  {
    switch (t)
      {
        case Turbulence::laminar: return "laminar";
        case Turbulence::k_epsilon: return "k-epsilon";
        case Turbulence::k_epsilon_launder_sharma: return "launder-sharma";
        case Turbulence::k_omega_sst: return "k-omega-sst";
      }
    return "?";
  }
} // namespace

int main(int argc, char **argv)
{
  constexpr auto nozzle = PilotGeometry::nozzle_flapper;
  constexpr auto orifice = PilotGeometry::fixed_orifice;
  const std::vector<ColdStart> cases{
    {"laminar null, resolution 2", nozzle, Turbulence::laminar, 2, 40e-6, 10.4e6, true, 0.6},
    {"laminar 60 um, resolution 2", nozzle, Turbulence::laminar, 2, 60e-6, 10.4e6, true, 0.6},
    {"Launder-Sharma null, resolution 1", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 40e-6, 10.4e6, true, 0.6},
    {"Launder-Sharma orifice, resolution 1", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 10.3e6, true, 0.6},
    {"orifice k-epsilon single phase, resolution 2", orifice, Turbulence::k_epsilon, 2, 0, 10.3e6, false, 0.6},
    {"orifice k-epsilon cavitating, resolution 1", orifice, Turbulence::k_epsilon, 1, 0, 10.3e6, true, 0.6},
    {"orifice k-epsilon cavitating, resolution 2", orifice, Turbulence::k_epsilon, 2, 0, 10.3e6, true, 0.6},
    {"60 um k-epsilon, realizability off, resolution 1", nozzle, Turbulence::k_epsilon, 1, 60e-6, 10.4e6, true, 0},
    {"SST null, resolution 1", nozzle, Turbulence::k_omega_sst, 1, 40e-6, 10.4e6, true, 0.6},
    {"SST 40 um at full pressure, resolution 1", nozzle, Turbulence::k_omega_sst, 1, 40e-6, 20.6e6, true, 0.6},
    {"SST orifice cavitating, resolution 1", orifice, Turbulence::k_omega_sst, 1, 0, 10.3e6, true, 0.6},
  };
  std::set<std::size_t> chosen;
  if (argc > 1)
    for (std::string list = argv[1]; !list.empty();)
      {
        const std::size_t comma = list.find(',');
        chosen.insert(std::strtoul(list.substr(0, comma).c_str(), nullptr, 10));
        list = comma == std::string::npos ? "" : list.substr(comma + 1);
      }
  std::printf("RV-1 at 40 degC, each case alone from rest\n");
  for (std::size_t n = 1; n <= cases.size(); ++n)
    {
      if (!chosen.empty() && !chosen.count(n))
        continue;
      const ColdStart &s = cases[n - 1];
      ValveDescription v = load_valve_description(
        "", {"Output/Progress=none", "Flow solver/Realizability coefficient=" + std::to_string(s.realizability)});
      v.pilot.field_cavitation = s.cavitation;
      PilotFieldCase c = pilot_field_case(v, 40);
      c.resolution = s.resolution;
      c.turbulence = s.model;
      const auto t0 = std::chrono::steady_clock::now();
      PilotField field(v, s.geometry, c, s.gap);
      std::printf("%2zu %-50s %-15s %7zu cells: ", n, s.what, name(s.model), field.n_cells());
      std::fflush(stdout);
      try
        {
          const PilotFieldResult r = field.solve(s.pressure_difference);
          std::printf("converged, %u iterations, %.1f s, C_d %.5f, F %.5f N\n", r.iterations + r.coarse_mesh_iterations,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                      r.discharge_coefficient, r.flapper_force);
        }
      catch (const std::exception &e)
        {
          std::printf("FAILED after %.1f s: %s\n",
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), e.what());
        }
      std::fflush(stdout);
    }
}
