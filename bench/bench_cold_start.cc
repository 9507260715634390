// Robustness of single field-level pilot cases started from rest (issue 28, item 6): the cases the
// issue lists as failing and those that failed in a model's sweep since, each solved alone from rest on RV-1 (40 degC unless stated; no continuation from a
// neighbouring case) on the flow stage's path (flow/pilot/pilot_field_cases.h's Chain: the case from rest
// with its pressure continuation, once more with half the continuation steps if that fails, SST and
// Launder-Sharma then from the two-layer k-epsilon's solution, and a case that still stalls marched in
// time for its time average), with every flow model. Cases 28-31 are the sweep's stalled hot orifice
// cases at 15.45 MPa on its path: after the chain's 1.03 MPa state, that state alone from rest (28,
// 29) or as the sweep's orifice path reaches it from 120 degC (30, 31). Cases 32 and 33 are cases 1 and
// 2 single phase, the flow the other code oscillates in at 40 um. Prints per case the outcome (converged, or flagged 2 with the solver's
// reason on stderr), the iterations, the wall time, C_d and the flapper force. Not a test (minutes).
//   OMP_THREAD_LIMIT=1 build/bench/bench_cold_start [case numbers, default all, e.g. 1,4,7] [parameter=value ...]
// (extra arguments are `--set' entries, e.g. 'Flow solver/Report interval=100' for the residual history)
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_cases.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
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
    double temperature = 40; ///< [degC]
    /// [Pa] if > 0: the chain first solves this pressure difference and starts the case from its
    /// fields, as the sweep does after the cases between were time-averaged or flagged
    double after_pressure_difference = 0;
    /// [degC] with after_pressure_difference: that case is solved as the sweep's orifice path does,
    /// at every table temperature (`Sweeps/Table temperatures') from this one down, each from the
    /// hotter's state
    double path_from = 0;
  };

  PilotFieldSolutionParameters::FlowModel flow_model(Turbulence t)
  {
    using M = PilotFieldSolutionParameters::FlowModel;
    switch (t)
      {
        case Turbulence::laminar: return M::laminar;
        case Turbulence::k_epsilon: return M::k_epsilon;
        case Turbulence::k_epsilon_launder_sharma: return M::k_epsilon_launder_sharma;
        case Turbulence::k_omega_sst: return M::k_omega_sst;
      }
    return M::automatic;
  }

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

int servodrift::bench::bench_cold_start(int argc, char **argv)
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
    {"SST 40 um at 120 degC, 3.09 MPa, resolution 1", nozzle, Turbulence::k_omega_sst, 1, 40e-6, 3.09e6, true, 0.6, 120},
    {"SST 40 um at 120 degC, 3.09 MPa, single phase", nozzle, Turbulence::k_omega_sst, 1, 40e-6, 3.09e6, false, 0.6, 120},
    {"SST orifice cavitating at 20.6 MPa, resolution 1", orifice, Turbulence::k_omega_sst, 1, 0, 20.6e6, true, 0.6},
    {"k-epsilon 40 um at 120 degC, 3.09 MPa, resolution 1", nozzle, Turbulence::k_epsilon, 1, 40e-6, 3.09e6, true, 0.6, 120},
    {"k-epsilon orifice cavitating at 20.6 MPa, resolution 1", orifice, Turbulence::k_epsilon, 1, 0, 20.6e6, true, 0.6},
    {"Launder-Sharma orifice at 120 degC, 1.03 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 1.03e6, true, 0.6, 120},
    {"Launder-Sharma 40 um at 120 degC, 3.09 MPa", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 40e-6, 3.09e6, true, 0.6, 120},
    {"Launder-Sharma 40 um at 120 degC, 3.09 MPa, single phase", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 40e-6, 3.09e6, false, 0.6, 120},
    {"Launder-Sharma 50 um at 110 degC, 10.3 MPa", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 50e-6, 10.3e6, true, 0.6, 110},
    {"Launder-Sharma 50 um at 110 degC, 10.3 MPa, single phase", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 50e-6, 10.3e6, false, 0.6, 110},
    {"Launder-Sharma 50 um at 110 degC, 10.3 MPa, single phase, resolution 2", nozzle, Turbulence::k_epsilon_launder_sharma, 2, 50e-6, 10.3e6, false, 0.6, 110},
    {"Launder-Sharma orifice at 110 degC, 10.3 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 10.3e6, true, 0.6, 110},
    {"Launder-Sharma 40 um at 100 degC, 20.6 MPa", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 40e-6, 20.6e6, true, 0.6, 100},
    {"Launder-Sharma 60 um at 100 degC, 10.3 MPa", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 60e-6, 10.3e6, true, 0.6, 100},
    {"Launder-Sharma 70 um at 90 degC, 10.3 MPa", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 70e-6, 10.3e6, true, 0.6, 90},
    {"Launder-Sharma 60 um at 100 degC, 10.3 MPa, single phase", nozzle, Turbulence::k_epsilon_launder_sharma, 1, 60e-6, 10.3e6, false, 0.6, 100},
    {"Launder-Sharma orifice at 100 degC, 15.45 MPa after 1.03 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 15.45e6, true, 0.6, 100, 1.03e6},
    {"Launder-Sharma orifice at 90 degC, 15.45 MPa after 1.03 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 15.45e6, true, 0.6, 90, 1.03e6},
    {"Launder-Sharma orifice at 100 degC, 15.45 MPa after the path's 1.03 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 15.45e6, true, 0.6, 100, 1.03e6, 120},
    {"Launder-Sharma orifice at 90 degC, 15.45 MPa after the path's 1.03 MPa", orifice, Turbulence::k_epsilon_launder_sharma, 1, 0, 15.45e6, true, 0.6, 90, 1.03e6, 120},
    {"laminar null, resolution 2, single phase", nozzle, Turbulence::laminar, 2, 40e-6, 10.4e6, false, 0.6},
    {"laminar 60 um, resolution 2, single phase", nozzle, Turbulence::laminar, 2, 60e-6, 10.4e6, false, 0.6},
  };
  std::set<std::size_t> chosen;
  std::vector<std::string> settings{"Output/Progress=none", "Output/Flow fields=none"};
  for (int a = 2; a < argc; ++a)
    settings.push_back(argv[a]);
  if (argc > 1 && std::string(argv[1]) != "all")
    for (std::string list = argv[1]; !list.empty();)
      {
        const std::size_t comma = list.find(',');
        chosen.insert(std::strtoul(list.substr(0, comma).c_str(), nullptr, 10));
        list = comma == std::string::npos ? "" : list.substr(comma + 1);
      }
  try // the settings given, once, before any case runs: a bad value gets one line, not an abort
    {
      load_valve_description("", settings);
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "bench_cold_start: %s\n", e.what());
      return 2;
    }
  std::printf("RV-1, each case alone from rest (40 degC unless its name says otherwise)\n");
  for (std::size_t n = 1; n <= cases.size(); ++n)
    {
      if (!chosen.empty() && !chosen.count(n))
        continue;
      const ColdStart &s = cases[n - 1];
      std::vector<std::string> these = settings;
      these.insert(these.begin() + 1, "Flow solver/Realizability coefficient=" + std::to_string(s.realizability));
      ValveDescription valve = load_valve_description("", these);
      valve.pilot.field_solution.cavitation = s.cavitation;
      valve.pilot.field_mesh.resolution = s.resolution;
      valve.pilot.field_solution.fixed_orifice_flow_model = valve.pilot.field_solution.nozzle_flow_model = flow_model(s.model);
      const auto t0 = std::chrono::steady_clock::now();
      std::printf("%2zu %-50s %-15s: ", n, s.what, name(s.model));
      std::fflush(stdout);
      Chain chain(valve, s.geometry, s.temperature);
      using namespace case_record;
      std::optional<FlowFields> hotter;
      const auto &table = valve.sweeps.table_temperatures;
      for (auto T = table.rbegin(); T != table.rend(); ++T)
        {
          if (*T > s.path_from || *T <= s.temperature)
            continue;
          Chain path(valve, s.geometry, *T);
          path.solve(s.gap, s.after_pressure_difference, hotter);
          if (const auto state = path.state())
            hotter = state->fields;
        }
      if (hotter)
        chain.solve(s.gap, s.after_pressure_difference, hotter);
      else if (s.after_pressure_difference > 0)
        chain.solve(s.gap, s.after_pressure_difference);
      const std::vector<double> r = chain.solve(s.gap, s.pressure_difference);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (r[flag] == flags::not_converged && r[averaged_time] > 0)
        std::printf("FAILED (flag 2): the mean of its time average over %.3g s is not used (stderr says why), C_d %.5f "
                    "+- %.5f (spread %.5f), F %.5f +- %.5f N (spread %.5f), %.0f steps at the iteration cap, "
                    "decorrelation lag %.0f steps, %.1f s\n",
                    r[averaged_time], r[averaged_discharge_coefficient], r[discharge_coefficient_uncertainty],
                    r[discharge_coefficient_spread], r[averaged_flapper_force], r[flapper_force_uncertainty],
                    r[flapper_force_spread], r[unconverged_steps], r[decorrelation_steps], seconds);
      else if (r[flag] == flags::not_converged)
        std::printf("FAILED (flag 2) after %.1f s\n", seconds);
      else if (r[flag] == flags::time_averaged)
        std::printf("time-averaged (flag 5: the steady iteration stalled) over %.3g s, %.0f iterations, %.1f s, C_d %.5f +- %.5f "
                    "(spread %.5f), F %.5f +- %.5f N (spread %.5f) (standard errors of the means; spreads: standard "
                    "deviations), %.0f averaged steps at the iteration cap, decorrelation lag %.0f steps of %.0f "
                    "averaged\n",
                    r[averaged_time], r[iterations], seconds, r[discharge_coefficient],
                    r[discharge_coefficient_uncertainty], r[discharge_coefficient_spread], r[flapper_force],
                    r[flapper_force_uncertainty], r[flapper_force_spread], r[unconverged_steps], r[decorrelation_steps],
                    std::round(r[averaged_time] / r[time_step]));
      else
        std::printf("converged, %.0f iterations, %.1f s, C_d %.5f, F %.5f N\n", r[iterations], seconds,
                    r[discharge_coefficient], r[flapper_force]);
      std::fflush(stdout);
    }
  return 0;
}
