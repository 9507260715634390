#pragma once
// The thermal null shift of one built valve (issue 25; model.md D8, C8): the valve is nulled at
// the reference temperature T0 by its hydraulic null adjustment, as a manufacturer does; what
// remains at the other temperatures is its thermal null shift. The measures: the null-shift current
// (primary), the pilot null pressure shift and the brake-pressure deviation at the rated current.
#include "system/valve_model.h"

#include <string>
#include <vector>

namespace servodrift::system
{
  struct ThermalNullShift
  {
    double hydraulic_null;                        ///< x_n set at T0 [m]
    std::vector<double> null_shift_current;       ///< per temperature [A]; a table-end bound if flagged
    std::vector<double> pilot_null_pressure;      ///< p_L - p_R at i = 0, per temperature [Pa]
    std::vector<double> brake_pressure_deviation; ///< p_B(T) - p_B(T0) at the rated current, less the ideal valve's [Pa]
    double maximum_null_shift;                    ///< max |null-shift current| over the temperatures [A]
    double temperature_of_maximum;                ///< where it occurs [degC]
    enum Flag : unsigned
    {
      null_beyond_table = 1,   ///< no null within the torque_motor table's currents at some T
      flapper_on_nozzle = 2,   ///< the flapper rests on a nozzle at i = 0 or rated somewhere
      spool_on_stop = 4,       ///< the spool rests on a stroke stop at i = 0 or rated somewhere
      outside_tables = 8       ///< the valve left the tables (nulling or an operating point): not evaluated
    };
    unsigned flags = 0;
  };

  /// Evaluates the thermal null shift of valves built with given offsets and deviations.
  class ThermalNullShiftEvaluator
  {
  public:
    /// `with_operating_points': also the pilot null pressure and the brake-pressure deviation (two
    /// static operating points per temperature); without, the null-shift current alone.
    ThermalNullShiftEvaluator(const ValveModel &model, std::vector<double> temperatures, bool with_operating_points);
    /// The valve's thermal null shift; a valve the tables do not reach (its nulling or an
    /// operating point beyond their range) is returned flagged `outside_tables', its measures 0.
    ThermalNullShift evaluate(const Offsets &build) const;
    /// What put such a valve outside the tables (the model's message), or empty.
    std::string why_outside(const Offsets &build) const;
    const std::vector<double> &temperatures() const { return temperatures_; }

  private:
    const ValveModel &model;
    std::vector<double> temperatures_;
    bool with_operating_points;
    double reference_temperature, rated_current;
    std::vector<double> ideal_brake_drift; ///< p_B(T) - p_B(T0) of the ideal valve at the rated current [Pa]

    ThermalNullShift evaluate_within_tables(const Offsets &build) const; ///< throws TableRangeError
  };
} // namespace servodrift::system
