#pragma once
// The dynamics' CSV outputs in <output>/system (units in every header, provenance in the comments):
// modes.csv, frequency_response.csv, step_response.csv, step_metrics.csv, sine_response.csv,
// dynamics_summary.csv and, for the fixed-time study, fixed_time_study.csv.
#include "common/valve_description.h"
#include "system/dynamics.h"

#include <string>

namespace servodrift::system
{
  void write_dynamics_tables(const ValveDescription &valve, const DynamicsResults &results, const std::string &directory);

  /// 20 log10 |h| [dB]
  double decibel(std::complex<double> h);
  /// arg h [deg]
  double degrees(std::complex<double> h);
} // namespace servodrift::system
