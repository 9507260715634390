#include "system/thermal_null_shift.h"

#include "common/error.h"

#include <cmath>
#include <utility>

namespace servodrift::system
{
  ThermalNullShiftEvaluator::ThermalNullShiftEvaluator(const ValveModel &model_, std::vector<double> temperatures,
                                                       bool with_operating_points_)
    : model(model_)
    , temperatures_(std::move(temperatures))
    , with_operating_points(with_operating_points_)
    , reference_temperature(model_.description().operating.reference_temperature)
    , rated_current(model_.description().operating.rated_current)
  {
    if (!with_operating_points)
      return;
    // C8: the ideal valve's own drift, which the brake-pressure deviation of a built valve leaves out
    const Offsets ideal;
    const double at_reference = model.solve(reference_temperature, rated_current, ideal).spool.brake_pressure;
    for (double T : temperatures_)
      ideal_brake_drift.push_back(model.solve(T, rated_current, ideal).spool.brake_pressure - at_reference);
  }

  ThermalNullShift ThermalNullShiftEvaluator::evaluate(const Offsets &build) const
  {
    try
      {
        return evaluate_within_tables(build);
      }
    catch (const TableRangeError &)
      {
        ThermalNullShift r;
        r.hydraulic_null = r.maximum_null_shift = 0;
        r.temperature_of_maximum = reference_temperature;
        r.flags = ThermalNullShift::outside_tables;
        const std::size_t n = temperatures_.size();
        r.null_shift_current.assign(n, 0.0);
        if (with_operating_points)
          {
            r.pilot_null_pressure.assign(n, 0.0);
            r.brake_pressure_deviation.assign(n, 0.0);
          }
        return r;
      }
  }

  std::string ThermalNullShiftEvaluator::why_outside(const Offsets &build) const
  {
    try
      {
        evaluate_within_tables(build);
        return "";
      }
    catch (const TableRangeError &e)
      {
        return e.what();
      }
  }

  ThermalNullShift ThermalNullShiftEvaluator::evaluate_within_tables(const Offsets &build) const
  {
    ThermalNullShift r;
    Offsets nulled = build;
    nulled.hydraulic_null = model.nulling_hydraulic_null(build); // D8: nulled at reference
    r.hydraulic_null = nulled.hydraulic_null;
    const auto note = [&r](const OperatingPoint &op) {
      if (op.flapper != FlapperState::free)
        r.flags |= ThermalNullShift::flapper_on_nozzle;
      if (op.spool.state == SpoolState::on_negative_stop || op.spool.state == SpoolState::on_positive_stop)
        r.flags |= ThermalNullShift::spool_on_stop;
    };
    double brake_at_reference = 0;
    if (with_operating_points)
      {
        const OperatingPoint rated = model.solve(reference_temperature, rated_current, nulled);
        note(rated);
        brake_at_reference = rated.spool.brake_pressure;
      }
    r.maximum_null_shift = -1;
    for (std::size_t t = 0; t < temperatures_.size(); ++t)
      {
        const double T = temperatures_[t];
        const ValveEquations eq = model.equations(T, nulled);
        const ValveModel::NullShift n = model.null_shift(eq);
        if (n.beyond_table)
          r.flags |= ThermalNullShift::null_beyond_table;
        r.null_shift_current.push_back(n.current);
        if (std::abs(n.current) > r.maximum_null_shift)
          {
            r.maximum_null_shift = std::abs(n.current);
            r.temperature_of_maximum = T;
          }
        if (with_operating_points)
          {
            const OperatingPoint zero = model.solve(eq, 0.0), rated = model.solve(eq, rated_current);
            note(zero);
            note(rated);
            r.pilot_null_pressure.push_back(zero.control_pressure_difference());
            r.brake_pressure_deviation.push_back(rated.spool.brake_pressure - brake_at_reference - ideal_brake_drift[t]);
          }
      }
    return r;
  }
} // namespace servodrift::system
