#include "system/calibration_model.h"

#include "common/error.h"
#include "system/valve_model.h"

#include <cstdio>
#include <map>
#include <utility>

namespace servodrift::system
{
  CalibrationModel::CalibrationModel(const CalibrationRequest &request_, std::vector<FreeParameter> parameters_,
                                     const StageTables &tables)
    : request(request_)
    , parameters(std::move(parameters_))
    , functions(tables)
    , descriptions(request_.input_file, overrides(std::vector<double>()))
  {}

  std::vector<std::string> CalibrationModel::overrides(const std::vector<double> &values) const
  {
    std::vector<std::string> o;
    for (const auto &entry : request.overrides)
      if (entry.rfind("Output/Directory=", 0) != 0)
        o.push_back(entry);
    for (std::size_t k = 0; k < values.size(); ++k)
      {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", values[k]); // round trip
        o.push_back(parameters[k].path + "=" + text);
      }
    return o;
  }

  std::vector<double> CalibrationModel::predict(const std::vector<double> &values,
                                                const std::vector<Measurement> &points) const
  {
    std::vector<std::pair<std::string, std::string>> entries;
    for (std::size_t k = 0; k < parameters.size(); ++k)
      {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", values[k]);
        entries.emplace_back(parameters[k].path, text);
      }
    const ValveDescription valve = descriptions.with(entries);
    const ValveModel model(valve, functions);
    // the valve as described, nulled by its convention (D8): what a bench measures
    const Offsets offsets = model.offsets_for_deviation(0.0);
    std::map<std::pair<double, double>, OperatingPoint> operating_points, ideal_points;
    const auto operating_point = [&](double T, double i, const Offsets &o) -> const OperatingPoint & {
      auto found = operating_points.find({T, i});
      if (found == operating_points.end())
        found = operating_points.emplace(std::make_pair(T, i), model.solve(T, i, o)).first;
      return found->second;
    };
    const auto ideal_point = [&](double T, double i) -> const OperatingPoint & {
      auto found = ideal_points.find({T, i});
      if (found == ideal_points.end())
        found = ideal_points.emplace(std::make_pair(T, i), model.solve(T, i, Offsets{})).first;
      return found->second;
    };
    std::map<double, double> null_shift;
    std::vector<double> y;
    for (const Measurement &p : points)
      {
        if (p.quantity == MeasuredQuantity::null_shift_current)
          {
            auto found = null_shift.find(p.temperature);
            if (found == null_shift.end())
              {
                const auto i = model.null_shift_current(p.temperature, offsets);
                if (!i)
                  throw TableRangeError("the null-shift current at " + format_number(p.temperature) +
                                        " degC lies beyond the torque_motor table's currents");
                found = null_shift.emplace(p.temperature, *i).first;
              }
            y.push_back(found->second);
            continue;
          }
        const OperatingPoint &op = operating_point(p.temperature, p.current, offsets);
        const bool deviation = p.quantity == MeasuredQuantity::spool_displacement_deviation ||
                               p.quantity == MeasuredQuantity::brake_pressure_deviation;
        // D9: the reference of a deviation, by the description's convention
        const OperatingPoint *reference = nullptr;
        if (deviation)
          reference = valve.offsets.nulling == OffsetParameters::Nulling::nulled_at_reference ?
                        &operating_point(valve.operating.reference_temperature, p.current, offsets) :
                        &ideal_point(p.temperature, p.current);
        switch (p.quantity)
          {
            case MeasuredQuantity::brake_pressure: y.push_back(op.spool.brake_pressure); break;
            case MeasuredQuantity::control_pressure_difference: y.push_back(op.control_pressure_difference()); break;
            case MeasuredQuantity::spool_displacement: y.push_back(op.spool.displacement); break;
            case MeasuredQuantity::spool_displacement_deviation:
              y.push_back(op.spool.displacement - reference->spool.displacement);
              break;
            case MeasuredQuantity::brake_pressure_deviation:
              y.push_back(op.spool.brake_pressure - reference->spool.brake_pressure);
              break;
            case MeasuredQuantity::null_shift_current: break;
          }
      }
    return y;
  }
} // namespace servodrift::system
