#pragma once
// The system model as a function of the calibration's free parameters: the valve description with
// the free entries set, its static operating points and null-shift currents at the measured
// temperatures and currents (issue 26). Any entry can be free: each evaluation reads the description
// anew, with the tables' interpolants built once.
#include "system/calibration.h"

namespace servodrift::system
{
  class CalibrationModel
  {
  public:
    CalibrationModel(const CalibrationRequest &request, std::vector<FreeParameter> parameters, const StageTables &tables);
    /// The request's overrides, without the output directory, and "path=value" of each free entry.
    std::vector<std::string> overrides(const std::vector<double> &values) const;
    /// The model's value of each point's quantity at its temperature and current (SI). Throws what
    /// the valve description or the model throws (a value outside a range, a point beyond a table).
    std::vector<double> predict(const std::vector<double> &values, const std::vector<Measurement> &points) const;

  private:
    CalibrationRequest request;
    std::vector<FreeParameter> parameters;
    StageFunctions functions;
    mutable ValveDescriptionVariants descriptions; ///< the request's description, read once
  };
} // namespace servodrift::system
