#include "common/parameters/dynamics.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void DynamicsParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    enabled = prm.get_bool("Enabled");
    bias = prm.get_double("Bias");
    small_step = prm.get_double("Small step");
    step_duration = prm.get_double("Step duration");
    minimum_frequency = prm.get_double("Minimum frequency");
    maximum_frequency = prm.get_double("Maximum frequency");
    frequency_points = prm.get_integer("Frequency points");
    sine_frequencies = prm.get_double_list("Sine frequencies");
    sine_check_amplitude = prm.get_double("Sine check amplitude");
    linearity_margin = prm.get_double("Linearity margin");
    sine_amplitudes = prm.get_double_list("Sine amplitudes");
    large_signal_temperatures = static_cast<unsigned int>(prm.get_integer("Large-signal temperatures"));
    cold_start_temperatures = prm.get_double_list("Cold-start temperatures");
    cold_start_current = prm.get_double("Cold-start current");
    samples_per_period = prm.get_integer("Samples per period");
    maximum_periods = prm.get_integer("Maximum periods");
    periodic_tolerance = prm.get_double("Periodic tolerance");
    relative_tolerance = prm.get_double("Relative tolerance");
    absolute_tolerance = prm.get_double("Absolute tolerance");
    maximum_steps = prm.get_integer("Maximum steps");
    fixed_time_study = prm.get_bool("Fixed-time study");
    reading_times = prm.get_double_list("Reading times");
    fixed_time_deviation_angles = prm.get_double_list("Fixed-time deviation angles");
    for (double &a : fixed_time_deviation_angles)
      a *= 3.14159265358979323846 / 180;
    prm.leave_subsection();
  }
} // namespace servodrift
