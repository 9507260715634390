#pragma once
// What `servodrift calibrate' writes (issue 26): calibration/result.json (estimates, standard
// errors, intervals, correlations, chi-square, warnings), calibration/fit.csv (each measured point
// with the model, the residual and the model's band), calibration/calibrated.prm (the valve with the
// estimates, ready for `servodrift run'), the plot of measured vs model over temperature with the
// band of the parameters' uncertainty, and the "Calibration" section of report.md.
#include "common/valve_description.h"
#include "system/calibration.h"
#include "system/plots.h"

#include <ostream>
#include <string>

namespace servodrift::system
{
  void write_calibration(const ValveDescription &valve, const CalibrationResults &results, const std::string &dir,
                         PlotFiles &plots);
  void calibration_section(std::ostream &out, const CalibrationResults &results);
} // namespace servodrift::system
