#pragma once
// The nonlinear frequency response (issue 23): the command i(t) = i_bias + a sin(2 pi f t), started
// on the linearisation's own periodic solution (so that a small amplitude starts periodic), is
// integrated period by period until the state recurs after one period or, for a sub-harmonic, after
// m periods (a periodic steady state); a slow approach is cut short by Newton steps of the shooting
// method on the map from one period start to the next. Then the first harmonic of each output over the input's, and
// how far the response is from linear: the harmonic distortion, the sub-harmonic content, the edges
// it crossed.
#include "common/parameters/dynamics.h"
#include "system/linear_analysis.h"
#include "system/valve_dynamics.h"

#include <array>
#include <complex>
#include <vector>

namespace servodrift::system
{
  /// The outputs of a sine response, in the order of its arrays.
  inline constexpr std::array<Output, 3> sine_outputs = {Output::brake_pressure, Output::spool_displacement,
                                                         Output::flapper_displacement};

  struct SineResponse
  {
    double frequency = 0;  ///< [Hz]
    double amplitude = 0;  ///< command amplitude [A]
    unsigned int periods = 0; ///< periods integrated [1]
    bool periodic = false; ///< the state recurred within `Dynamics/Maximum periods'
    unsigned int response_periods = 1; ///< the response repeats after this many input periods (> 1: a sub-harmonic) [1]
    unsigned int shooting_steps = 0;   ///< Newton steps of the shooting method, each a restart [1]
    double last_change = 0; ///< scaled change of the state over the last period / the motion [1]
    std::array<std::complex<double>, 3> gain{};   ///< first harmonic / input's, per output [unit/A]
    std::array<double, 3> minimum{}, maximum{};  ///< over the last period [SI]
    double distortion = 0;  ///< total harmonic distortion of p_B: harmonics 2-10 / first [1]
    double subharmonic = 0; ///< p_B's content below f (lines j f/m), relative to its first harmonic [1]
    bool flapper_contact = false; ///< the flapper touched a nozzle in the last period
    bool beyond_lap = false;      ///< the spool opened a metering edge in the last period
    bool spool_on_stop = false;   ///< the spool reached a stroke limit in the last period
    bool left_tables = false; ///< a pressure went beyond the flow tables (constant C_d)
    std::string failure;      ///< why the time integration stopped, if it did (then not periodic)
    std::vector<double> final_state; ///< the state at the last period's end (input phase 0); not archived
  };

  /// `bias_point' is the static operating point at the bias command `bias' [A], `linearisation' the
  /// valve linearised there. `start', if given, is the state to start from at input phase 0 (a
  /// neighbouring frequency's final_state, for a sweep); otherwise the linear periodic solution or,
  /// for a large amplitude, the bias point.
  SineResponse sine_response(const ValveDynamics &dynamics, const Linearisation &linearisation,
                             const ValveState &bias_point, double bias, double frequency, double amplitude,
                             const DynamicsParameters &parameters, const std::vector<double> *start = nullptr);

  /// The small-signal sine check: the nonlinear first harmonic of p_B against the linearisation,
  /// within these limits, at an amplitude where halving it moves that harmonic by at most
  /// `halving_fraction' of them (the linear limit: what remains of the difference is not the
  /// amplitude's). A first-harmonic departure of a smooth nonlinearity falls as the amplitude
  /// squared, so each halving cuts it to a quarter; `halvings' bounds how far the amplitude goes.
  struct SineCheckLimits
  {
    static constexpr double decibel = 0.5, degree = 3, halving_fraction = 0.1;
    static constexpr unsigned int halvings = 8;
  };

  /// The small-signal sine at one frequency: at the largest amplitude whose linear excursion stays
  /// within `Dynamics/Linearity margin' of the edges, then halved until the linear limit, beside
  /// the linearisation.
  struct SineCheck
  {
    double frequency = 0;                            ///< [Hz]
    std::array<std::complex<double>, 3> linear{};    ///< H of p_B, x_v, x_f (sine_outputs) [unit/A]
    std::array<std::complex<double>, 3> dc_gain{};   ///< H(0) of the same, the reference of every dB [unit/A]
    std::vector<SineResponse> halvings;              ///< the amplitude and each half of it, in order
    bool linear_limit = false; ///< the last halving moved p_B's first harmonic within the fraction
    /// The response the check takes: at the smallest amplitude
    const SineResponse &taken() const { return halvings.back(); }
    /// p_B's first harmonic at the taken amplitude over the one before it (1 if none)
    std::complex<double> last_halving() const
    {
      return halvings.size() > 1 ? halvings.back().gain[0] / halvings[halvings.size() - 2].gain[0] : 1.0;
    }
  };

  /// The check at frequency f about the bias point (stable there), by SineCheckLimits.
  SineCheck sine_check(const ValveDynamics &dynamics, const Linearisation &linearisation, const ValveState &bias_point,
                       double bias, double frequency, double largest_amplitude, const DynamicsParameters &parameters);

  /// The largest amplitude, up to `largest', whose linear response keeps the spool and the flapper
  /// within `margin' of the distance from the bias to their nearest edge (lap edges, stops, nozzles).
  double linear_amplitude(const ValveDynamics &dynamics, const Linearisation &linearisation,
                          const ValveState &bias_point, double frequency, double largest, double margin);
} // namespace servodrift::system
