#include "system/tolerance_study.h"

#include "common/error.h"
#include "common/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>

namespace servodrift::system
{
  Offsets built_valve(const ValveModel &model, const std::vector<std::size_t> &quantities, const std::vector<double> &row)
  {
    Offsets o = model.described_offsets();
    auto &[l, r] = o.sides;
    for (std::size_t k = 0; k < quantities.size(); ++k)
      {
        const double x = row[k];
        switch (quantities[k]) // the order of ToleranceParameters::quantities()
          {
            case 0: l.orifice_diameter += x; break;
            case 1: r.orifice_diameter += x; break;
            case 2: l.nozzle_diameter += x; break;
            case 3: r.nozzle_diameter += x; break;
            case 4: l.null_gap += x; break;
            case 5: r.null_gap += x; break;
            case 6: l.orifice_discharge_factor += x; break;
            case 7: r.orifice_discharge_factor += x; break;
            case 8: l.nozzle_discharge_factor += x; break;
            case 9: r.nozzle_discharge_factor += x; break;
            case 10: o.spring_tube_rest_angle += x; break;
            case 11: o.magnetic_null += x; break;
            case 12: o.magnetic.lower_gap_mismatch += x; break;
            case 13: o.magnetic.left_remanence += x; break;
            case 14: o.magnetic.right_remanence += x; break;
            default: break;
          }
      }
    return o;
  }

  SampleRows evaluate_rows(const std::string &label, const SampleRows &rows,
                           const std::function<std::vector<double>(const std::vector<double> &)> &evaluate,
                           OutputParameters::Progress progress)
  {
    // blocks of rows per case: the runner's hand-out costs a message per case, a valve ~1 ms
    const std::size_t block = 16, n_cases = (rows.size() + block - 1) / block;
    return run_sweep(
      label, n_cases,
      [&](std::size_t c) {
        CaseRows out;
        for (std::size_t i = c * block; i < std::min(rows.size(), (c + 1) * block); ++i)
          out.push_back(evaluate(rows[i]));
        return out;
      },
      progress);
  }

  SobolStudy sobol_study(const ToleranceParameters &t, const std::vector<std::string> &outputs,
                         const std::function<std::vector<double>(const std::vector<double> &)> &evaluate,
                         OutputParameters::Progress progress, double floor)
  {
    SobolStudy s;
    s.base_samples = t.sobol_base_samples;
    s.standard_deviation_floor = floor;
    s.outputs = outputs;
    const SampleRows design = sobol_design(t);
    s.evaluations = design.size();
    const SampleRows values = evaluate_rows("system: Sobol' design", design, evaluate, progress);
    for (std::size_t k = 0; k < outputs.size(); ++k)
      {
        std::vector<double> y;
        for (const auto &v : values)
          y.push_back(v[k]);
        s.indices.push_back(sobol_indices(t, design, y, floor));
        std::vector<double> a; // the A block's values that exist
        std::copy_if(y.begin(), y.begin() + t.sobol_base_samples, std::back_inserter(a),
                     [](double v) { return std::isfinite(v); });
        double mean = 0, var = 0;
        for (double v : a)
          mean += v / double(a.size());
        for (double v : a)
          var += (v - mean) * (v - mean) / double(std::max<std::size_t>(a.size(), 2) - 1);
        s.output_variance.push_back(var);
      }
    return s;
  }

  namespace
  {
    std::vector<double> pack(const ThermalNullShift &v)
    {
      std::vector<double> r{v.hydraulic_null, v.maximum_null_shift, v.temperature_of_maximum, double(v.flags)};
      for (const auto *list : {&v.null_shift_current, &v.pilot_null_pressure, &v.brake_pressure_deviation})
        r.insert(r.end(), list->begin(), list->end());
      return r;
    }

    ThermalNullShift unpack(const std::vector<double> &r, std::size_t n_T)
    {
      ThermalNullShift v;
      v.hydraulic_null = r[0];
      v.maximum_null_shift = r[1];
      v.temperature_of_maximum = r[2];
      v.flags = unsigned(r[3]);
      std::size_t k = 4;
      for (auto *list : {&v.null_shift_current, &v.pilot_null_pressure, &v.brake_pressure_deviation})
        {
          list->assign(r.begin() + k, r.begin() + k + n_T);
          k += n_T;
        }
      return v;
    }

    /// Seconds per valve of an evaluator, measured on the first few valves of the study
    double seconds_per_valve(const ValveModel &model, const ToleranceResults &r, const ThermalNullShiftEvaluator &e)
    {
      const std::size_t n = std::min<std::size_t>(4, r.inputs.size());
      const auto start = std::chrono::steady_clock::now();
      for (std::size_t k = 0; k < n; ++k)
        e.evaluate(built_valve(model, r.quantities, r.inputs[k]));
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / double(std::max<std::size_t>(n, 1));
    }

    /// Work that takes long is announced before it starts: the Monte Carlo and the Sobol' design at
    /// the cost per valve measured on the first valves, shared over the ranks, and the Sobol'
    /// bootstrap (about 30 ns per output, resample and design row, on every rank).
    void announce_cost(const ValveModel &model, const ToleranceResults &r, const ThermalNullShiftEvaluator &full,
                       OutputParameters::Progress progress)
    {
      if (progress == OutputParameters::Progress::none)
        return;
      const ToleranceParameters &t = model.description().tolerances;
      const double ranks = double(mpi_size()), per_valve = seconds_per_valve(model, r, full);
      const double monte_carlo = double(r.inputs.size()) * per_valve / ranks;
      double sobol = 0;
      const double design = double(t.sobol_base_samples) * double(r.quantities.size() + 2);
      if (t.sobol_base_samples > 0)
        {
          const ThermalNullShiftEvaluator null_only(model, r.temperatures, false);
          sobol = design * seconds_per_valve(model, r, null_only) / ranks + 3 * 30e-9 * double(t.bootstrap_size) * design;
        }
      const double total = monte_carlo + sobol;
      if (total < 10 || mpi_rank() != 0)
        return;
      const auto duration = [](double seconds) {
        char text[32];
        if (seconds < 120)
          std::snprintf(text, sizeof(text), "%.0f s", seconds);
        else if (seconds < 7200)
          std::snprintf(text, sizeof(text), "%.0f min", seconds / 60);
        else
          std::snprintf(text, sizeof(text), "%.1f h", seconds / 3600);
        return std::string(text);
      };
      std::cout << "system: tolerance study: about " << duration(total) << " on " << mpi_size() << " rank(s): "
                << r.inputs.size() << " valves x " << r.temperatures.size() << " temperatures at "
                << format_number(1e3 * per_valve) << " ms per valve (" << duration(monte_carlo) << ")";
      if (t.sobol_base_samples > 0)
        std::cout << ", the Sobol' design of " << format_number(design) << " valves with " << t.bootstrap_size
                  << " bootstrap resamples (" << duration(sobol) << ")";
      std::cout << std::endl;
    }

    /// A valve outside the tables, for the report: its index, its largest deviation (in standard
    /// deviations, or half-widths of a uniform) with the entry and value, and the model's reason.
    std::string outside_example(const ValveModel &model, const ToleranceParameters &t,
                                const std::vector<std::size_t> &quantities, const std::vector<double> &row,
                                std::size_t index, const ThermalNullShiftEvaluator &evaluator)
    {
      std::size_t worst = 0;
      double worst_size = -1;
      for (std::size_t k = 0; k < quantities.size(); ++k)
        {
          const ToleranceDistribution &d = t.distributions[quantities[k]];
          const double spread = d.kind == ToleranceDistribution::Kind::uniform ? 0.5 * (d.upper - d.lower) : d.standard_deviation;
          const double size = spread > 0 ? std::abs(row[k] - d.mean) / spread : 0;
          if (size > worst_size)
            worst_size = size, worst = k;
        }
      const ToleranceDistribution &d = t.distributions[quantities[worst]];
      char size[16];
      std::snprintf(size, sizeof(size), "%.3g", worst_size);
      return "valve " + std::to_string(index) + ", whose largest deviation is `Tolerances/" + d.name + "' = " +
             format_number(row[worst]) + " " + d.unit + " (" + size +
             (d.kind == ToleranceDistribution::Kind::uniform ? " half-widths" : " standard deviations") +
             "): " + evaluator.why_outside(built_valve(model, quantities, row));
    }

    MeasureStatistics statistics_of(std::string measure, std::string unit, std::optional<double> T,
                                     const std::vector<double> &values)
    {
      MeasureStatistics m{std::move(measure), std::move(unit), T, 0, 0, {}};
      for (double v : values)
        m.mean += v / double(values.size());
      double sum = 0;
      for (double v : values)
        sum += (v - m.mean) * (v - m.mean);
      m.standard_deviation = values.size() > 1 ? std::sqrt(sum / double(values.size() - 1)) : 0.0;
      m.quantiles = quantiles(values, ToleranceResults::probabilities);
      return m;
    }
  } // namespace

  ToleranceResults compute_tolerances(const ValveModel &model, OutputParameters::Progress progress)
  {
    const auto &valve = model.description();
    const ToleranceParameters &t = valve.tolerances;
    ToleranceResults r;
    r.quantities = t.active();
    r.temperatures = valve.sweeps.drift_temperatures;
    r.rated_current = valve.operating.rated_current;
    r.spec_text = t.null_shift_spec_text(valve.operating.reference_temperature);
    for (double T : r.temperatures)
      r.limits.push_back(t.null_shift_limit(T, valve.operating.reference_temperature));
    r.confidence_level = t.confidence_level;
    const std::size_t n_T = r.temperatures.size();

    // Monte Carlo: every measure of every valve
    r.inputs = draw_valves(t);
    const ThermalNullShiftEvaluator full(model, r.temperatures, true);
    announce_cost(model, r, full, progress);
    const SampleRows values = evaluate_rows(
      "system: tolerance study", r.inputs,
      [&](const std::vector<double> &row) { return pack(full.evaluate(built_valve(model, r.quantities, row))); },
      progress);
    r.passes = 0;
    for (const auto &v : values)
      {
        r.valves.push_back(unpack(v, n_T));
        const ThermalNullShift &valve_result = r.valves.back();
        bool pass = !(valve_result.flags & (ThermalNullShift::null_beyond_table | ThermalNullShift::outside_tables));
        for (std::size_t k = 0; k < n_T; ++k)
          pass = pass && t.within_null_shift_spec(valve_result.null_shift_current[k], r.temperatures[k], r.rated_current,
                                                  valve.operating.reference_temperature);
        r.pass.push_back(pass);
        r.passes += pass;
        if (valve_result.flags & ThermalNullShift::outside_tables && r.outside_tables++ == 0)
          r.outside_example = outside_example(model, t, r.quantities, r.inputs[r.valves.size() - 1], r.valves.size() - 1,
                                              full);
      }
    r.yield_interval = proportion_interval(r.passes, r.valves.size(), t.confidence_level);

    // Statistics over the valves within the tables: over the range, then the envelopes at each temperature
    const auto column = [&](auto &&value) {
      std::vector<double> c;
      for (const auto &v : r.valves)
        if (!(v.flags & ThermalNullShift::outside_tables))
          c.push_back(value(v));
      return c;
    };
    if (r.outside_tables == r.valves.size())
      return r; // no valve to take statistics of, nor a Sobol' study worth its cost
    const auto max_abs = [](const std::vector<double> &list) {
      double m = 0;
      for (double x : list)
        m = std::max(m, std::abs(x));
      return m;
    };
    r.statistics.push_back(statistics_of("maximum_abs_null_shift_current", "%", std::nullopt, column([&](const auto &v) {
                                           return 100 * v.maximum_null_shift / r.rated_current;
                                         })));
    r.statistics.push_back(statistics_of("maximum_abs_pilot_null_pressure", "Pa", std::nullopt,
                                         column([&](const auto &v) { return max_abs(v.pilot_null_pressure); })));
    r.statistics.push_back(statistics_of("maximum_abs_brake_pressure_deviation", "Pa", std::nullopt,
                                         column([&](const auto &v) { return max_abs(v.brake_pressure_deviation); })));
    for (std::size_t k = 0; k < n_T; ++k)
      {
        const double T = r.temperatures[k];
        r.statistics.push_back(statistics_of("null_shift_current", "mA", T, column([&](const auto &v) {
                                               return 1e3 * v.null_shift_current[k];
                                             })));
        r.statistics.push_back(statistics_of("pilot_null_pressure", "Pa", T,
                                             column([&](const auto &v) { return v.pilot_null_pressure[k]; })));
        r.statistics.push_back(statistics_of("brake_pressure_deviation", "Pa", T,
                                             column([&](const auto &v) { return v.brake_pressure_deviation[k]; })));
      }

    // Sobol': the null-shift current alone, over the range and at the two ends [% of rated]. Its
    // floor, a millionth of a percent of rated (0.2 nA of 20 mA), lies far below any null-shift
    // spec (about 1-4 % of rated) and far above the round-off of the nulling and null-shift
    // roots (below 1e-9 %): at the nulling temperature every valve's null shift is that round-off.
    constexpr double null_shift_floor = 1e-6; // [% of rated]
    if (t.sobol_base_samples > 0)
      {
        const ThermalNullShiftEvaluator null_only(model, r.temperatures, false);
        r.sobol = sobol_study(
          t,
          {"maximum_abs_null_shift_current", "null_shift_current_at_" + format_number(r.temperatures.front()) + "degC",
           "null_shift_current_at_" + format_number(r.temperatures.back()) + "degC"},
          [&](const std::vector<double> &row) {
            const ThermalNullShift v = null_only.evaluate(built_valve(model, r.quantities, row));
            const double percent = 100 / r.rated_current;
            if (v.flags & ThermalNullShift::outside_tables) // no value: the indices are then undefined
              return std::vector<double>(3, std::numeric_limits<double>::quiet_NaN());
            return std::vector<double>{percent * v.maximum_null_shift, percent * v.null_shift_current.front(),
                                       percent * v.null_shift_current.back()};
          },
          progress, null_shift_floor);
      }
    return r;
  }
} // namespace servodrift::system
