#pragma once
// The valve linearised at an operating point: y' = A y + B i_command. Its modes (eigenvalues named
// after the states that take part in them, with natural frequency and damping ratio), and the
// transfer functions from the command current to the outputs on a frequency grid, with the -3 dB
// bandwidth and the -90 degree frequency.
#include "system/valve_dynamics.h"

#include <Eigen/Dense>

#include <array>
#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace servodrift::system
{
  struct Linearisation
  {
    Eigen::MatrixXd A;          ///< dF/dy
    Eigen::VectorXd B;          ///< dF/di_command
    std::vector<double> scales; ///< of the states (ValveDynamics::scales)
    double pivot_to_nozzle_distance; ///< r, for the flapper output [m]
  };
  Linearisation linearise(const ValveDynamics &dynamics, const ValveState &point, double command_current);

  struct Mode
  {
    std::complex<double> eigenvalue; ///< [1/s]; of a complex pair, the one with Im > 0
    std::string name;                ///< the groups of states with a quarter or more of the participation
    double natural_frequency;        ///< |lambda|/(2 pi) [Hz]
    double damping_ratio;            ///< -Re(lambda)/|lambda| [1]; 1 for a real pole
    std::array<double, n_state_groups> participation; ///< by StateGroup, summing to 1
  };
  /// The modes, by natural frequency; a complex pair once. Participation factors |v_ki w_ik| (right
  /// and left eigenvectors of the scaled matrix), normalised per mode, summed per group.
  std::vector<Mode> modes(const Linearisation &linearisation);
  /// The smallest decay rate -Re(lambda) of the modes [1/s]: what sets the time to settle.
  double slowest_decay_rate(const Linearisation &linearisation);
  /// The eigenvalues of a square matrix (scaled by `scales'), sorted by magnitude.
  std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd &A, const std::vector<double> &scales);

  enum class Output
  {
    brake_pressure,               ///< p_B [Pa]
    spool_displacement,           ///< x_v [m]
    flapper_displacement,         ///< x_f = r theta (a change of x_n does not move it) [m]
    control_pressure_difference   ///< p_L - p_R [Pa]
  };
  const char *to_string(Output output);
  /// The output of a state vector.
  double output_of(const Linearisation &linearisation, Output output, const std::vector<double> &y);

  /// H(j 2 pi f) = C (j 2 pi f I - A)^-1 B [output unit per A]; f = 0 gives the DC gain.
  std::complex<double> transfer(const Linearisation &linearisation, Output output, double frequency);
  /// The state response phasor X(f) = (j 2 pi f I - A)^-1 B per ampere of command.
  Eigen::VectorXcd state_response(const Linearisation &linearisation, double frequency);

  struct FrequencyResponse
  {
    Output output;
    std::complex<double> dc_gain;              ///< H(0) [unit/A]
    std::vector<double> frequencies;           ///< [Hz]
    std::vector<std::complex<double>> values;  ///< H [unit/A]
    std::vector<double> amplitude_db;          ///< 20 log10 |H/H(0)| [dB]
    std::vector<double> phase_degrees;         ///< arg(H/H(0)), continuous from the lowest frequency [deg]
    std::optional<double> bandwidth;           ///< first crossing of -3 dB [Hz]
    std::optional<double> phase_90_frequency;  ///< first crossing of -90 degrees [Hz]
  };
  /// On `points' log-spaced frequencies from f_min to f_max; crossings refined between grid points.
  FrequencyResponse frequency_response(const Linearisation &linearisation, Output output, double minimum_frequency,
                                       double maximum_frequency, unsigned int points);
} // namespace servodrift::system
