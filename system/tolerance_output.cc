#include "system/tolerance_output.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"
#include "common/version.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace servodrift::system
{
  std::string snake_case(const std::string &name)
  {
    std::string s;
    for (char ch : name)
      s += ch == ' ' || ch == '-' ? '_' : char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
  }

  namespace
  {
    std::string cell(double v)
    {
      if (!std::isfinite(v))
        throw std::logic_error("tolerance output: a non-finite value reached a CSV cell");
      return format_cell(v);
    }

    std::string quantity_name(std::size_t q)
    {
      return ToleranceParameters::quantities()[q].first;
    }

    std::string estimator_name(ToleranceParameters::SobolEstimator e)
    {
      switch (e)
        {
          case ToleranceParameters::SobolEstimator::saltelli: return "Saltelli";
          case ToleranceParameters::SobolEstimator::jansen: return "Jansen";
          case ToleranceParameters::SobolEstimator::martinez: return "Martinez";
          case ToleranceParameters::SobolEstimator::mauntz_kucherenko: return "Mauntz-Kucherenko";
        }
      return "?";
    }

    std::string sampling_name(ToleranceParameters::Sampling s)
    {
      switch (s)
        {
          case ToleranceParameters::Sampling::monte_carlo: return "Monte Carlo";
          case ToleranceParameters::Sampling::latin_hypercube: return "Latin hypercube";
          case ToleranceParameters::Sampling::randomised_sobol_sequence: return "randomised Sobol' sequence";
        }
      return "?";
    }

    std::vector<std::string> comments(const ValveDescription &valve, const std::string &name, const ToleranceResults &r)
    {
      const auto &t = valve.tolerances;
      return {"servodrift-output " + name,
              std::to_string(r.valves.size()) + " valves (" + sampling_name(t.sampling) + ", seed " +
                std::to_string(t.seed) + "), each nulled at " + format_number(valve.operating.reference_temperature) +
                " degC by its hydraulic null adjustment (D8); spec |null-shift current| <= " + r.spec_text +
                " (" + format_number(1e3 * r.rated_current) + " mA)",
              "producer " + producer_string("system/tolerances"), "parameters-sha256 " + valve.parameters_sha256};
    }

    /// A percentage in the report: three decimals (a null shift at T0 is zero up to the root finding)
    std::string percent_text(double value)
    {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", std::abs(value) < 5e-4 ? 0.0 : value);
      return text;
    }

    std::string temperature_label(double T)
    {
      return format_number(T) + "degC";
    }

    /// The three quantities of largest total index of the first Sobol' output (the maximum null shift).
    std::vector<std::size_t> largest_contributors(const ToleranceResults &r, std::size_t how_many)
    {
      std::vector<std::size_t> order(r.quantities.size());
      std::iota(order.begin(), order.end(), 0);
      const auto &total = r.sobol->indices.front().total;
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return total[a] > total[b]; });
      order.resize(std::min(how_many, order.size()));
      return order;
    }

    const MeasureStatistics *find(const ToleranceResults &r, const std::string &measure, std::optional<double> T)
    {
      for (const auto &m : r.statistics)
        if (m.measure == measure && m.temperature == T)
          return &m;
      return nullptr;
    }
  } // namespace

  void write_tolerance_tables(const ValveDescription &valve, const ToleranceResults &r, const std::string &dir)
  {
    // every valve
    CsvDocument samples;
    samples.comments = comments(valve, "tolerance_samples", r);
    samples.comments.push_back("flags: null_beyond_table = no null within the torque_motor table's currents at some "
                               "temperature (the null-shift current is then the table's end, a bound); "
                               "flapper_on_nozzle, spool_on_stop at i = 0 or rated somewhere; outside_tables = the "
                               "valve's nulling or an operating point lies beyond the tables: not evaluated (empty "
                               "cells), failing");
    samples.columns = {"valve[1]"};
    for (std::size_t q : r.quantities)
      samples.columns.push_back(snake_case(quantity_name(q)) + "_deviation[" + ToleranceParameters::quantities()[q].second + "]");
    for (const char *c : {"hydraulic_null[m]", "maximum_abs_null_shift_current[mA]", "maximum_abs_null_shift_current[%]",
                          "temperature_of_maximum[degC]", "pass[-]", "null_beyond_table[-]", "flapper_on_nozzle[-]",
                          "spool_on_stop[-]", "outside_tables[-]"})
      samples.columns.push_back(c);
    for (const char *measure : {"null_shift_current", "pilot_null_pressure", "brake_pressure_deviation"})
      for (double T : r.temperatures)
        samples.columns.push_back(std::string(measure) + "_at_" + temperature_label(T) +
                                  (std::string(measure) == "null_shift_current" ? "[mA]" : "[Pa]"));
    for (std::size_t k = 0; k < r.valves.size(); ++k)
      {
        const ThermalNullShift &v = r.valves[k];
        std::vector<std::string> row{std::to_string(k)};
        for (double x : r.inputs[k])
          row.push_back(cell(x));
        const bool outside = v.flags & ThermalNullShift::outside_tables;
        const auto value = [&](double x) { return outside ? std::string() : cell(x); }; // none: not evaluated
        row.insert(row.end(), {value(v.hydraulic_null), value(1e3 * v.maximum_null_shift),
                               value(100 * v.maximum_null_shift / r.rated_current), value(v.temperature_of_maximum),
                               r.pass[k] ? "1" : "0", v.flags & ThermalNullShift::null_beyond_table ? "1" : "0",
                               v.flags & ThermalNullShift::flapper_on_nozzle ? "1" : "0",
                               v.flags & ThermalNullShift::spool_on_stop ? "1" : "0", outside ? "1" : "0"});
        for (double x : v.null_shift_current)
          row.push_back(value(1e3 * x));
        for (const auto *list : {&v.pilot_null_pressure, &v.brake_pressure_deviation})
          for (double x : *list)
            row.push_back(value(x));
        samples.rows.push_back(row);
      }
    write_file_atomically(dir + "/tolerance_samples.csv", samples.text());

    // statistics and yield
    CsvDocument summary;
    summary.comments = comments(valve, "tolerance_summary", r);
    summary.comments.push_back("statistics over the valves; an empty temperature: over the drift temperatures; "
                               "the yield row: the fraction within the spec, its exact (Clopper-Pearson) " +
                               format_number(100 * r.confidence_level) + " % interval in the interval columns");
    summary.columns = {"measure[-]", "unit[-]", "temperature[degC]", "mean[unit]", "standard_deviation[unit]",
                       "quantile_01[unit]", "quantile_05[unit]", "quantile_50[unit]", "quantile_95[unit]",
                       "quantile_99[unit]", "interval_lower[unit]", "interval_upper[unit]"};
    summary.rows.push_back({"yield", "1", "", cell(r.yield()), "", "", "", "", "", "", cell(r.yield_interval.lower),
                            cell(r.yield_interval.upper)});
    for (const auto &m : r.statistics)
      {
        std::vector<std::string> row{m.measure, m.unit, m.temperature ? cell(*m.temperature) : "", cell(m.mean),
                                     cell(m.standard_deviation)};
        for (double q : m.quantiles)
          row.push_back(cell(q));
        row.insert(row.end(), {"", ""});
        summary.rows.push_back(row);
      }
    write_file_atomically(dir + "/tolerance_summary.csv", summary.text());

    if (!r.sobol)
      return;
    const auto &s = *r.sobol;
    const auto &t = valve.tolerances;
    CsvDocument sobol;
    sobol.comments = comments(valve, "sobol_indices", r);
    sobol.comments.push_back("first-order and total Sobol' indices (" + estimator_name(t.sobol_estimator) +
                             " estimator, OpenTURNS) of each output, N = " + std::to_string(s.base_samples) + ", " +
                             std::to_string(s.evaluations) + " valves; " + format_number(100 * t.confidence_level) +
                             " % bootstrap intervals of " + std::to_string(t.bootstrap_size) + " resamples");
    sobol.comments.push_back("an output whose standard deviation over the design is at most " +
                             format_number(s.standard_deviation_floor) +
                             " % of rated has no variance to share out: its indices are undefined (empty cells), "
                             "the reason in note");
    for (std::size_t o = 0; o < s.outputs.size(); ++o)
      if (!s.indices[o].defined())
        sobol.comments.push_back(s.outputs[o] + ": indices undefined, " + s.indices[o].undefined);
    sobol.columns = {"output[-]", "quantity[-]", "first_order[1]", "first_order_lower[1]", "first_order_upper[1]",
                     "total[1]", "total_lower[1]", "total_upper[1]", "output_variance[%^2]", "note[-]"};
    for (std::size_t o = 0; o < s.outputs.size(); ++o)
      for (std::size_t k = 0; k < r.quantities.size(); ++k)
        {
          const auto &ix = s.indices[o];
          const std::string quantity = snake_case(quantity_name(r.quantities[k]));
          if (ix.defined())
            sobol.rows.push_back({s.outputs[o], quantity, cell(ix.first_order[k]), cell(ix.first_order_interval[k].lower),
                                  cell(ix.first_order_interval[k].upper), cell(ix.total[k]),
                                  cell(ix.total_interval[k].lower), cell(ix.total_interval[k].upper),
                                  cell(s.output_variance[o]), ""});
          else
            sobol.rows.push_back({s.outputs[o], quantity, "", "", "", "", "", "",
                                  std::isfinite(s.output_variance[o]) ? cell(s.output_variance[o]) : "",
                                  "undefined: " + ix.undefined});
        }
    write_file_atomically(dir + "/sobol_indices.csv", sobol.text());
  }

  void write_tolerance_plots(const ValveDescription &valve, const ToleranceResults &r, const std::string &dir,
                             PlotFiles &files)
  {
    if (!valve.output.plots)
      return;
    prepare_output_directory(dir);
    const double percent = 100 / r.rated_current;
    // envelope: T, q01, q05, q50, q95, q99 of the null-shift current and the spec [% of rated]
    std::ostringstream envelope;
    envelope << "# temperature[degC] null-shift current [% of rated]: q01 q05 q50 q95 q99, allowed\n";
    double extent = 0; // the y range shows the spec and every quantile
    for (std::size_t k = 0; k < r.temperatures.size(); ++k)
      {
        const MeasureStatistics *m = find(r, "null_shift_current", r.temperatures[k]);
        envelope << format_cell(r.temperatures[k]);
        for (double q : m->quantiles)
          {
            envelope << ' ' << format_cell(1e-3 * q * percent);
            extent = std::max(extent, std::abs(1e-3 * q * percent));
          }
        envelope << ' ' << format_cell(100 * r.limits[k]) << '\n';
        extent = std::max(extent, 100 * r.limits[k]);
      }
    write_file_atomically(dir + "/tolerance_envelope.dat", envelope.str());
    // empirical CDF of the maximum |null shift|
    std::vector<double> maxima;
    for (const auto &v : r.valves)
      maxima.push_back(percent * v.maximum_null_shift);
    std::sort(maxima.begin(), maxima.end());
    std::ostringstream cdf;
    cdf << "# maximum |null-shift current| [% of rated], fraction of valves at or below [1]\n";
    for (std::size_t k = 0; k < maxima.size(); ++k)
      cdf << format_cell(maxima[k]) << ' ' << format_cell(double(k + 1) / double(maxima.size())) << '\n';
    write_file_atomically(dir + "/tolerance_cdf.dat", cdf.str());

    const std::string range = format_cell(r.temperatures.front()) + ":" + format_cell(r.temperatures.back());
    std::vector<Plot> plots = {
      {"tolerance_envelope",
       "set title 'Thermal null shift of " + std::to_string(r.valves.size()) + " valves nulled at " +
         format_number(valve.operating.reference_temperature) + " degC'\nset grid\nset key outside right\n"
         "set xlabel 'temperature [degC]'\nset ylabel 'null-shift current [% of rated]'\nset xrange [" + range + "]\n"
         "set yrange [" + format_cell(-1.15 * extent) + ":" + format_cell(1.15 * extent) + "]\n"
         "plot 'tolerance_envelope.dat' using 1:3:5 with filledcurves fs transparent solid 0.3 lc 'blue' title '5-95 %', "
         "'' using 1:2 with lines dt 2 lc 'blue' title '1 %', '' using 1:6 with lines dt 2 lc 'blue' title '99 %', "
         "'' using 1:4 with linespoints lw 2 lc 'blue' title 'median', '' using 1:7 with lines lc 'red' title "
         "'spec', '' using 1:(-$7) with lines lc 'red' notitle\n"},
      {"tolerance_cdf",
       "set title 'Maximum |null shift| over the drift temperatures'\nset grid\nset key bottom right\n"
       "set xlabel 'maximum |null-shift current| [% of rated]'\nset ylabel 'fraction of valves [1]'\nset yrange [0:1]\n"
       "plot 'tolerance_cdf.dat' using 1:2 with steps lw 2 lc 'blue' title 'empirical CDF'\n"}};
    if (r.sobol && r.sobol->indices.front().defined())
      {
        std::ostringstream bars;
        bars << "# quantity first_order[1] lower upper total[1] lower upper (output: maximum |null shift|)\n";
        const auto &ix = r.sobol->indices.front();
        for (std::size_t k = 0; k < r.quantities.size(); ++k)
          bars << '"' << quantity_name(r.quantities[k]) << "\" " << format_cell(ix.first_order[k]) << ' '
               << format_cell(ix.first_order_interval[k].lower) << ' ' << format_cell(ix.first_order_interval[k].upper)
               << ' ' << format_cell(ix.total[k]) << ' ' << format_cell(ix.total_interval[k].lower) << ' '
               << format_cell(ix.total_interval[k].upper) << '\n';
        write_file_atomically(dir + "/sobol_indices.dat", bars.str());
        plots.push_back({"sobol_indices",
                         "set title \"Sobol' indices of the maximum |null shift|\"\nset grid y\nset style data histograms\n"
                         "set style histogram errorbars gap 1 lw 1\nset style fill solid 0.6 border -1\n"
                         "set xtics rotate by -35\nset bmargin 9\nset rmargin 10\nset yrange [0:1.05]\nset ylabel 'index [1]'\nset key top right\n"
                         "plot 'sobol_indices.dat' using 2:3:4:xtic(1) title 'first order', '' using 5:6:7 title 'total'\n"});
      }
    render_plots(valve, plots, dir, files);
  }

  void tolerance_section(std::ostream &out, const ValveDescription &valve, const ToleranceResults &r)
  {
    const auto &t = valve.tolerances;
    const double percent = 100 / r.rated_current;
    out << "## Tolerances\n\n"
        << r.valves.size() << " valves drawn (" << sampling_name(t.sampling) << ", seed " << t.seed
        << ") from the tolerances of " << r.quantities.size() << " quantities, each valve nulled at "
        << format_number(valve.operating.reference_temperature)
        << " degC by its hydraulic null adjustment (D8); its thermal null shift is the current that restores the "
           "pilot null (p_L = p_R) at each drift temperature.\n\n"
        << "**Yield** against the spec |null-shift current| <= " << r.spec_text << " at every drift temperature, "
        << format_number(r.temperatures.front())
        << " to " << format_number(r.temperatures.back()) << " degC: **" << format_number(100 * r.yield()) << " %** ("
        << r.passes << " of " << r.valves.size() << "), " << format_number(100 * r.confidence_level)
        << " % interval " << format_number(100 * r.yield_interval.lower) << " to "
        << format_number(100 * r.yield_interval.upper) << " % (exact binomial).\n\n";
    std::size_t beyond = 0;
    for (const auto &v : r.valves)
      beyond += (v.flags & ThermalNullShift::null_beyond_table) != 0;
    if (beyond)
      out << beyond << " valves have no null within the torque_motor table's currents somewhere (counted as failing; "
          << "their null-shift current is the table's end, a bound).\n\n";
    if (r.outside_tables)
      out << "**" << r.outside_tables << " of " << r.valves.size()
          << " valves lie outside the tables** (their nulling or an operating point beyond the tables' range): "
             "counted as failing, not evaluated, so the yield is a lower bound and the statistics below are of the "
          << r.valves.size() - r.outside_tables << " others. The first: " << r.outside_example
          << ". Narrow the tolerance that drives them, or extend the tables (`Sweeps`).\n\n";
    if (const MeasureStatistics *m = find(r, "maximum_abs_null_shift_current", std::nullopt))
      out << "Maximum |null shift| over the range: median " << percent_text(m->quantiles[2]) << " %, 95 % of valves below "
          << percent_text(m->quantiles[3]) << " %, 99 % below " << percent_text(m->quantiles[4]) << " % of rated.\n\n";
    if (r.sobol)
      {
        out << "**Largest contributors** to the maximum |null shift| (total Sobol' index, " << estimator_name(t.sobol_estimator)
            << ", N = " << r.sobol->base_samples << ", " << format_number(100 * t.confidence_level) << " % interval):\n\n";
        const auto &ix = r.sobol->indices.front();
        if (!ix.defined())
          out << "(none: " << ix.undefined << ")\n";
        else
          for (std::size_t k : largest_contributors(r, 3))
            out << "1. " << quantity_name(r.quantities[k]) << ": total " << format_number(ix.total[k]) << " ["
                << format_number(ix.total_interval[k].lower) << ", " << format_number(ix.total_interval[k].upper)
                << "], first order " << format_number(ix.first_order[k]) << "\n";
        for (std::size_t o = 1; o < r.sobol->outputs.size(); ++o)
          if (!r.sobol->indices[o].defined())
            out << "\n`" << r.sobol->outputs[o] << "` has no indices: " << r.sobol->indices[o].undefined << ".\n";
        out << "\nEvery index, also of the null shift at the coldest and the hottest temperature: "
               "`system/sobol_indices.csv`.\n\n";
      }
    out << "Drift envelope of the null-shift current [% of rated]:\n\n"
        << "| T [degC] | 1 % | 5 % | median | 95 % | 99 % |\n|---:|---:|---:|---:|---:|---:|\n";
    for (double T : r.temperatures)
      if (const MeasureStatistics *m = find(r, "null_shift_current", T))
        {
          out << "| " << format_number(T);
          for (double q : m->quantiles)
            out << " | " << percent_text(1e-3 * q * percent);
          out << " |\n";
        }
    out << "\nEvery valve: `system/tolerance_samples.csv`; statistics of every measure (also the pilot null pressure "
           "and the brake-pressure deviation at the rated current): `system/tolerance_summary.csv`.\n\n";
  }
} // namespace servodrift::system
