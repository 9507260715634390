#pragma once
// The dynamics of the whole valve at each drift temperature (issue 23): modes and the linear
// frequency response at the bias, the closed-form checks, the steady-state check, two step
// responses, and the nonlinear sine responses (the linearity check and the large-signal study). The
// cases (a temperature's linear analyses and steps; a temperature and a sine frequency) are shared
// over the MPI ranks; the results are the same, bit for bit, on any number of ranks.
#include "common/parameters/output.h"
#include "system/dynamic_checks.h"
#include "system/fixed_time_study.h"
#include "system/linear_analysis.h"
#include "system/sine_response.h"
#include "system/steady_state_check.h"
#include "system/step_response.h"
#include "system/valve_model.h"

#include <array>
#include <complex>
#include <optional>
#include <vector>

namespace servodrift::system
{
  struct TemperatureDynamics
  {
    double temperature = 0;  ///< [degC]
    double bias = 0;         ///< bias command [A]
    ValveState bias_point;   ///< static operating point at the bias
    double hydraulic_null = 0; ///< x_n of the valve (x_f = r theta - x_n) [m]
    SpoolState bias_spool_state = SpoolState::regulating;
    std::vector<Mode> modes; ///< at the bias
    FrequencyResponse brake_pressure, spool_displacement; ///< at the bias
    DynamicChecks checks;
    SteadyStateCheck steady;
    StepResponse large_step; ///< 0 -> rated current
    StepResponse small_step; ///< bias -> bias + small step
    std::vector<SineCheck> sine_checks;                ///< by `Dynamics/Sine frequencies'; none if unstable
    /// the large-signal study, [frequency][amplitude]: frequencies swept up, each starting from the
    /// periodic state of the one below, and down likewise (none if unstable). Where the two differ
    /// the valve has two periodic responses at one frequency, and a sweep jumps between them.
    std::vector<std::vector<SineResponse>> sine_study, sine_study_down; ///< empty where not studied
    /// every mode decays at the bias (else the sine responses are not computed)
    bool stable() const;
  };

  /// A cold-soak start (issue 65): the valve at rest at one temperature, supply and command applied
  struct ColdStart
  {
    double temperature = 0; ///< [degC]
    StepResponse response;  ///< from rest (start_up_response)
  };

  struct DynamicsResults
  {
    std::vector<TemperatureDynamics> temperatures; ///< the drift temperatures
    std::vector<ColdStart> cold_starts;            ///< at `Dynamics/Cold-start temperatures'
    std::vector<FixedTimeStudy> fixed_time;        ///< model.md C9, when `Dynamics/Fixed-time study'
  };

  DynamicsResults compute_dynamics(const ValveModel &model, OutputParameters::Progress progress);

  /// The indices of `count' of n temperatures, the ends and the others evenly spread (rounded);
  /// all n if count >= n: where the large-signal study runs (`Dynamics/Large-signal temperatures').
  std::vector<std::size_t> study_indices(std::size_t n, std::size_t count);

  /// Up and down sweeps differ at this frequency and amplitude: both periodic, and their first
  /// harmonics of p_B more than 1 dB or 10 degrees apart: two periodic responses at one frequency,
  /// between which a sweep jumps (issue 23).
  bool sweeps_differ(const SineResponse &up, const SineResponse &down);

  /// The armature's amplifier: u = R_c(T0) i_command under voltage drive [Ohm].
  double amplifier_resistance(const ValveDescription &valve);
} // namespace servodrift::system
