#pragma once
// report.md: the stage coefficients, operating points and drift maps of a run beside model.md's
// RV-1 values and the paper's numbers (model.md sections 2 and 3).
#include "common/valve_description.h"
#include "system/plots.h"

#include <string>

namespace servodrift::system
{
  struct SystemResults;

  /// A number for report.md: `digits' significant digits, "n/a" if not finite.
  std::string report_number(double value, int digits = 4);
  void write_report(const ValveDescription &valve, const SystemResults &results, const PlotFiles &plots,
                    const std::string &path);
} // namespace servodrift::system
