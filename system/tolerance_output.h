#pragma once
// What the tolerance study writes (issue 25): system/tolerance_samples.csv (every valve: its
// deviations and measures), system/tolerance_summary.csv (statistics, envelopes, yield),
// system/sobol_indices.csv, the plots (drift envelope, distribution of the maximum null shift,
// Sobol' indices) and the "Tolerances" section of report.md.
#include "common/valve_description.h"
#include "system/plots.h"
#include "system/tolerance_study.h"

#include <ostream>
#include <string>

namespace servodrift::system
{
  void write_tolerance_tables(const ValveDescription &valve, const ToleranceResults &results, const std::string &dir);
  void write_tolerance_plots(const ValveDescription &valve, const ToleranceResults &results, const std::string &dir,
                             PlotFiles &files);
  void tolerance_section(std::ostream &out, const ValveDescription &valve, const ToleranceResults &results);
  /// "Left orifice diameter" -> "left_orifice_diameter"
  std::string snake_case(const std::string &name);
} // namespace servodrift::system
