#pragma once
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Dynamics": the time-domain and frequency-domain analyses of the whole valve at each
  /// drift temperature (model.md 1.12-1.20; issue 23). Currents are fractions of the rated current.
  struct DynamicsParameters
  {
    static constexpr const char *subsection = "Dynamics";
    bool enabled;                       ///< run the analyses in `servodrift run'
    double bias;                        ///< bias current / rated current [1]
    double small_step;                  ///< small step around the bias / rated current [1]
    double step_duration;               ///< [s]; 0: from the slowest mode of the linearisation
    double minimum_frequency;           ///< linear frequency response from ... [Hz]
    double maximum_frequency;           ///< ... to [Hz]
    unsigned int frequency_points;      ///< log-spaced points of the linear frequency response [1]
    std::vector<double> sine_frequencies; ///< nonlinear sine inputs [Hz]
    double sine_check_amplitude;        ///< largest amplitude of the linearity check / rated [1]
    double linearity_margin;            ///< linear excursion / distance to the nearest edge [1]
    std::vector<double> sine_amplitudes; ///< amplitudes of the large-signal study / rated [1]
    unsigned int large_signal_temperatures; ///< how many drift temperatures the study runs at [1]
    std::vector<double> cold_start_temperatures; ///< of the cold-soak start-ups (issue 65) [degC]
    double cold_start_current;          ///< their command / rated [1]
    unsigned int samples_per_period;    ///< output samples per period for the harmonics [1]
    unsigned int maximum_periods;       ///< periods allowed to reach a periodic steady state [1]
    double periodic_tolerance;          ///< change of the first harmonic between two periods [1]
    double relative_tolerance;          ///< CVODE rtol [1]
    double absolute_tolerance;          ///< CVODE atol, per state scale [1]
    unsigned int maximum_steps;         ///< CVODE steps per output interval [1]
    bool fixed_time_study;              ///< model.md C9: read the start-up transient at fixed times
    std::vector<double> reading_times;  ///< times of the fixed-time readings [s]
    std::vector<double> fixed_time_deviation_angles; ///< theta_d of the fixed-time study [rad] (declared in degree)

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
