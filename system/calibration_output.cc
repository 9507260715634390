#include "system/calibration_output.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/json.h"
#include "common/output_files.h"
#include "common/version.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace servodrift::system
{
  namespace
  {
    std::string cell(double v)
    {
      if (!std::isfinite(v))
        throw std::logic_error("calibration output: a non-finite value reached a CSV cell");
      return format_cell(v);
    }

    /// A quantity's name in a plot (gnuplot would read `_' as a subscript)
    std::string label(MeasuredQuantity q)
    {
      std::string text = name(q);
      std::replace(text.begin(), text.end(), '_', ' ');
      return text;
    }

    /// The plotted unit of a quantity and its factor from SI.
    std::pair<std::string, double> shown_unit(MeasuredQuantity q)
    {
      switch (q)
        {
          case MeasuredQuantity::null_shift_current: return {"mA", 1e3};
          case MeasuredQuantity::spool_displacement:
          case MeasuredQuantity::spool_displacement_deviation: return {"um", 1e6};
          default: return {"MPa", 1e-6};
        }
    }
  } // namespace

  void write_calibration(const ValveDescription &valve, const CalibrationResults &r, const std::string &dir,
                         PlotFiles &plots)
  {
    const CalibrationRequest &request = r.request;
    prepare_output_directory(dir);
    const auto &params = r.setup.parameters;
    const std::size_t p = params.size();

    Json estimates = Json::array();
    for (std::size_t j = 0; j < p; ++j)
      {
        Json e = Json::object();
        e.set("entry", params[j].path).set("unit", params[j].unit).set("start", params[j].initial)
          .set("lower_bound", params[j].lower).set("upper_bound", params[j].upper).set("estimate", r.estimates[j])
          .set("standard_error", r.standard_errors[j] ? Json(*r.standard_errors[j]) : Json())
          .set("interval_lower", r.intervals[j] ? Json(r.intervals[j]->lower) : Json())
          .set("interval_upper", r.intervals[j] ? Json(r.intervals[j]->upper) : Json())
          .set("identifiable", bool(r.standard_errors[j]));
        estimates.push_back(e);
      }
    Json determined = Json::array();
    for (const auto &c : r.determined)
      {
        Json terms = Json::array();
        for (std::size_t k = 0; k < c.paths.size(); ++k)
          {
            Json t = Json::object();
            t.set("entry", c.paths[k]).set("coefficient", c.coefficients[k]);
            terms.push_back(t);
          }
        Json e = Json::object();
        e.set("combination", c.text()).set("terms", terms).set("unit", c.unit).set("estimate", c.estimate)
          .set("standard_error", c.standard_error);
        determined.push_back(e);
      }
    Json correlation = Json::array();
    for (const auto &row : r.correlation)
      correlation.push_back(Json(row));
    Json doc = Json::object();
    doc.set("producer", producer_string("system/calibration"))
      .set("parameters-sha256", valve.parameters_sha256)
      .set("measured", request.measured_file)
      .set("points", r.setup.data.points.size())
      .set("estimates", estimates)
      .set("correlation", correlation)
      .set("confidence_level", r.confidence_level)
      .set("interval_factor", r.interval_factor)
      .set("chi_square", r.chi_square)
      .set("degrees_of_freedom", r.degrees_of_freedom)
      .set("reduced_chi_square", r.reduced_chi_square)
      .set("sigma_estimated_from_the_fit", r.sigma_estimated)
      .set("rank", r.rank)
      .set("not_identifiable", r.not_identifiable)
      .set("determined_combinations", determined)
      .set("warnings", r.warnings)
      .set("iterations", r.iterations)
      .set("solver", r.termination);
    write_file_atomically(dir + "/result.json", doc.dump());

    CsvDocument fit;
    fit.comments = {"servodrift-output calibration_fit", "measured " + request.measured_file +
                                                           ", model at the estimates; residual = model - measured; "
                                                           "band: the model's standard deviation from the estimates' covariance",
                    "producer " + producer_string("system/calibration"), "parameters-sha256 " + valve.parameters_sha256};
    fit.columns = {"line[1]", "temperature[degC]", "current[A]", "quantity[-]", "unit[-]", "measured[unit]",
                   "standard_deviation[unit]", "model[unit]", "residual[unit]", "normalised_residual[1]",
                   "model_standard_deviation[unit]"};
    for (std::size_t k = 0; k < r.setup.data.points.size(); ++k)
      {
        const Measurement &m = r.setup.data.points[k];
        fit.rows.push_back({std::to_string(m.line), cell(m.temperature), cell(m.current), name(m.quantity), si_unit(m.quantity),
                            cell(m.value), cell(r.weights[k]), cell(r.model[k]), cell(r.model[k] - m.value),
                            cell((r.model[k] - m.value) / r.weights[k]), cell(r.model_standard_deviation[k])});
      }
    write_file_atomically(dir + "/fit.csv", fit.text());

    write_file_atomically(dir + "/calibrated.prm",
                          "# servodrift: the valve calibrated to " + request.measured_file + " (calibration/result.json)\n" +
                            print_parameters(request.input_file, r.calibrated_overrides, ParameterFormat::prm));

    if (!valve.output.plots)
      return;
    // measured points and model curves with their 95 % band, one panel per quantity
    std::ostringstream data;
    data << "# blocks: per series (quantity, current), the model curve: T[degC] model band_low band_high; "
            "then the measured points: T[degC] value sd\n";
    std::string commands;
    std::size_t block = 0;
    for (const auto &c : r.curves)
      {
        const auto [unit, f] = shown_unit(c.quantity);
        data << "# " << name(c.quantity) << " at " << c.current << " A, model\n";
        for (std::size_t k = 0; k < c.temperatures.size(); ++k)
          data << format_cell(c.temperatures[k]) << ' ' << format_cell(f * c.values[k]) << ' '
               << format_cell(f * (c.values[k] - r.interval_factor * c.standard_deviations[k])) << ' '
               << format_cell(f * (c.values[k] + r.interval_factor * c.standard_deviations[k])) << '\n';
        data << "\n\n# measured\n";
        for (std::size_t k = 0; k < r.setup.data.points.size(); ++k)
          {
            const Measurement &m = r.setup.data.points[k];
            if (m.quantity == c.quantity && m.current == c.current)
              data << format_cell(m.temperature) << ' ' << format_cell(f * m.value) << ' ' << format_cell(f * r.weights[k]) << '\n';
          }
        data << "\n\n";
        const std::string title = "at " + format_number(1e3 * c.current) + " mA";
        commands += "set ylabel '" + label(c.quantity) + " [" + unit + "]'\nplot 'calibration_fit.dat' index " +
                    std::to_string(block) + " using 1:3:4 with filledcurves fs transparent solid 0.3 lc 'blue' title '95 % band', '' index " +
                    std::to_string(block) + " using 1:2 with lines lw 2 lc 'blue' title 'model: " + title + "', '' index " +
                    std::to_string(block + 1) + " using 1:2:3 with yerrorbars pt 7 lc 'black' title 'measured'\n";
        block += 2;
      }
    prepare_output_directory(dir + "/plots");
    write_file_atomically(dir + "/plots/calibration_fit.dat", data.str());
    render_plots(valve,
                 {{"calibration_fit", "set multiplot layout " + std::to_string(r.curves.size()) +
                                        ",1 title 'Measured and calibrated model'\nset grid\nset key top right box opaque\n"
                                        "set xlabel 'temperature [degC]'\n" + commands + "unset multiplot\n"}},
                 dir + "/plots", plots);
  }

  void calibration_section(std::ostream &out, const CalibrationResults &r)
  {
    const auto &params = r.setup.parameters;
    out << "## Calibration\n\n"
        << "The valve of this report is calibrated to `" << r.setup.data.file << "` (" << r.setup.data.points.size()
        << " measured values): weighted least squares on the system model (Ceres, " << r.iterations
        << " iterations), " << (r.sigma_estimated ? "the noise estimated from the residuals (Student's t)" :
                                                    "the standard deviations of the file (normal)")
        << ".\n\n| entry | start | estimate | standard error | 95 % interval | unit |\n|---|---:|---:|---:|---|---|\n";
    for (std::size_t j = 0; j < params.size(); ++j)
      out << "| `" << params[j].path << "` | " << format_number(params[j].initial) << " | " << format_number(r.estimates[j])
          << " | " << (r.standard_errors[j] ? format_number(*r.standard_errors[j]) : "not identifiable") << " | "
          << (r.intervals[j] ? format_number(r.intervals[j]->lower) + " to " + format_number(r.intervals[j]->upper) : "-")
          << " | " << params[j].unit << " |\n";
    if (!r.determined.empty())
      {
        out << "\nWhat the data determine of the entries they cannot tell apart:\n\n"
            << "| combination | estimate | standard error | unit |\n|---|---:|---:|---|\n";
        for (const auto &c : r.determined)
          out << "| " << c.text() << " | " << format_number(c.estimate) << " | " << format_number(c.standard_error)
              << " | " << c.unit << " |\n";
      }
    out << "\nThe data determine " << r.rank << " of " << params.size() << " directions of the " << params.size()
        << " free entries; " << r.setup.data.points.size() << " values, " << r.degrees_of_freedom
        << " degrees of freedom.\n";
    if (r.sigma_estimated)
      out << "\nThe residuals' standard deviation, sqrt(chi-square/" << r.degrees_of_freedom << "), is "
          << format_number(std::sqrt(r.reduced_chi_square)) << " " << si_unit(r.setup.data.points.front().quantity)
          << ": the noise the intervals assume.\n\n";
    else
      out << "\nChi-square " << format_number(r.chi_square) << " on " << r.degrees_of_freedom
          << " degrees of freedom, reduced chi-square " << format_number(r.reduced_chi_square)
          << " (about 1 when the model fits to the stated noise; well above 1: the model or the standard deviations "
             "miss something).\n\n";
    for (const auto &w : r.warnings)
      out << "**Warning:** " << w << "\n\n";
    out << "Every point: `calibration/fit.csv`; estimates, correlations: `calibration/result.json`; the valve with the "
           "estimates: `calibration/calibrated.prm`.\n\n";
  }
} // namespace servodrift::system
