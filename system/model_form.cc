#include "system/model_form.h"

#include "common/csv.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/version.h"
#include "system/report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace servodrift::system
{
  namespace
  {
    /// The three quantities the choice of flow model moves, by index.
    double quantity(const StageCoefficients &c, int q)
    {
      return q == 0 ? c.nozzle_discharge : q == 1 ? c.null_flapper_force : c.flow_force_stiffness;
    }
    const char *const quantity_name[3] = {"C_dn at null", "flapper force at null [N]", "K_f [N/m]"};

    std::size_t not_converged_rows(const Table &t)
    {
      std::size_t n = 0;
      for (const auto &row : t.rows)
        n += row.back() == flags::not_converged;
      return n;
    }

    /// The models' smallest and largest value of quantity q at drift temperature k.
    std::pair<double, double> range(const std::vector<ModelFormCoefficients> &models, std::size_t k, int q)
    {
      double lo = quantity(models.front().coefficients[k], q), hi = lo;
      for (const auto &m : models)
        lo = std::min(lo, quantity(m.coefficients[k], q)), hi = std::max(hi, quantity(m.coefficients[k], q));
      return {lo, hi};
    }
  } // namespace

  std::vector<ModelFormCoefficients> model_form_coefficients(const ValveDescription &valve, const StageTables &tables,
                                                             const std::vector<StageCoefficients> &default_coefficients,
                                                             const std::string &directory,
                                                             std::vector<std::string> &warnings)
  {
    std::vector<ModelFormCoefficients> models{
      {"default", default_coefficients, not_converged_rows(tables.fixed_orifice) + not_converged_rows(tables.nozzle_flapper)}};
    for (const std::string &model : valve.pilot.field_solution.model_form_alternatives)
      {
        if (!std::filesystem::exists(directory + "/nozzle_flapper." + model + ".csv") ||
            !std::filesystem::exists(directory + "/fixed_orifice." + model + ".csv"))
          {
            warnings.push_back("`Pilot stage/Field solution/Model-form alternatives' lists " + model + ", but tables/ has no " +
                               "nozzle_flapper." + model + ".csv or fixed_orifice." + model +
                               ".csv (run the flow stage): left out of the model-form uncertainty");
            continue;
          }
        const StageTables alternative = tables.with_pilot_variant(directory, model);
        const ValveModel model_of_alternative(valve, alternative);
        ModelFormCoefficients m{model, {}, not_converged_rows(alternative.fixed_orifice) +
                                             not_converged_rows(alternative.nozzle_flapper)};
        for (const auto &c : default_coefficients)
          m.coefficients.push_back(stage_coefficients(model_of_alternative, c.temperature));
        models.push_back(std::move(m));
      }
    return models;
  }

  void write_model_form_table(const ValveDescription &valve, const std::vector<ModelFormCoefficients> &models,
                              const std::string &dir)
  {
    {
      CsvDocument doc;
      doc.comments = {"servodrift-output model_form_spread",
                      "the stage coefficients the choice of flow model moves (issue 28): each model's C_dn and flapper "
                      "force at null and K_f (E24) from its own pilot tables through the same valve model, and their "
                      "deviation from the default's; not_converged_rows: its pilot tables' rows that carry the "
                      "reduced-order value (flag 2)",
                      "producer " + producer_string("system"), "parameters-sha256 " + valve.parameters_sha256};
      doc.columns = {"temperature[degC]",        "flow_model[-]",
                     "nozzle_discharge[1]",      "null_flapper_force[N]",
                     "flow_force_stiffness[N/m]", "nozzle_discharge_deviation[1]",
                     "null_flapper_force_deviation[1]", "flow_force_stiffness_deviation[1]",
                     "not_converged_rows[1]"};
      const auto &reference = models.front().coefficients;
      for (std::size_t k = 0; k < reference.size(); ++k)
        for (const auto &m : models)
          {
            const StageCoefficients &c = m.coefficients[k];
            doc.rows.push_back({format_cell(c.temperature), m.model, format_cell(c.nozzle_discharge),
                                format_cell(c.null_flapper_force), format_cell(c.flow_force_stiffness)});
            for (int q = 0; q < 3; ++q)
              doc.rows.back().push_back(format_cell(quantity(c, q) / quantity(reference[k], q) - 1));
            doc.rows.back().push_back(format_cell(double(m.flagged_rows)));
          }
      write_file_atomically(dir + "/model_form_spread.csv", doc.text());
    }
  }

  void write_model_form_plots(const ValveDescription &valve, const std::vector<ModelFormCoefficients> &models,
                              const std::string &dir, PlotFiles &files)
  {
    // one data file: T, then per quantity the default, the band's low and high, then each model
    std::ostringstream data;
    data << "# temperature[degC]";
    for (int q = 0; q < 3; ++q)
      {
        data << " | " << quantity_name[q] << ": default low high";
        for (const auto &m : models)
          data << " " << m.model;
      }
    data << "\n";
    const auto &reference = models.front().coefficients;
    for (std::size_t k = 0; k < reference.size(); ++k)
      {
        data << reference[k].temperature;
        for (int q = 0; q < 3; ++q)
          {
            const auto [lo, hi] = range(models, k, q);
            data << " " << quantity(reference[k], q) << " " << lo << " " << hi;
            for (const auto &m : models)
              data << " " << quantity(m.coefficients[k], q);
          }
        data << "\n";
      }
    prepare_output_directory(dir);
    write_file_atomically(dir + "/model_form.dat", data.str());
    std::ostringstream body;
    body << "set multiplot layout 1,3 title 'Model-form uncertainty of the pilot stage: the band spans the flow models'\n"
         << "set xlabel 'temperature [degC]'\nset key bottom left font ',8'\nset grid\n";
    const std::size_t columns_per_quantity = 3 + models.size();
    for (int q = 0; q < 3; ++q)
      {
        const std::size_t first = 2 + q * columns_per_quantity; // the default's column
        body << "set ylabel '" << quantity_name[q] << "'\n"
             << "plot 'model_form.dat' using 1:" << first + 1 << ":" << first + 2
             << " with filledcurves lc rgb '#c0d8f0' title 'range of the models', \\\n";
        for (std::size_t j = 0; j < models.size(); ++j)
          body << "     'model_form.dat' using 1:" << first + 3 + j << " with linespoints title '" << models[j].model
               << "'" << (j + 1 < models.size() ? ", \\\n" : "\n");
      }
    body << "unset multiplot\n";
    render_plots(valve, {{"model_form", body.str()}}, dir, files);
  }

  void model_form_section(std::ostream &out, const std::vector<ModelFormCoefficients> &models)
  {
    out << "## Model-form uncertainty of the pilot stage\n\n";
    if (models.size() < 2)
      {
        out << "Not computed in this run (`Pilot stage/Field solution/Model-form alternatives`: the flow stage computes the "
               "tables of other flow models beside the default's).\n\n";
        return;
      }
    out << "The same stage coefficients from each flow model's own pilot tables (";
    for (std::size_t j = 0; j < models.size(); ++j)
      out << (j ? ", " : "") << models[j].model;
    out << "; `system/model_form_spread.csv`, `system/plots/model_form.*`): the range the choice of model leaves "
           "open.\n\n| T [degC] | C_dn at null: default [range] | flapper force at null [N] | K_f [N/m] |\n|---|---|---|---|\n";
    const auto &reference = models.front().coefficients;
    double widest[3] = {0, 0, 0};
    for (std::size_t k = 0; k < reference.size(); ++k)
      {
        out << "| " << report_number(reference[k].temperature, 3);
        for (int q = 0; q < 3; ++q)
          {
            const auto [lo, hi] = range(models, k, q);
            const double value = quantity(reference[k], q);
            widest[q] = std::max(widest[q], (hi - lo) / std::abs(value));
            out << " | " << report_number(value) << " [" << report_number(lo) << ", " << report_number(hi) << "]";
          }
        out << " |\n";
      }
    out << "\nThe widest range relative to the default: C_dn " << report_number(100 * widest[0], 2)
        << " %, flapper force " << report_number(100 * widest[1], 2) << " %, K_f " << report_number(100 * widest[2], 2)
        << " %.";
    for (const auto &m : models)
      if (m.flagged_rows > 0)
        out << " " << m.model << ": " << m.flagged_rows
            << " rows of its pilot tables did not converge and carry the reduced-order value.";
    out << "\n\n";
  }
} // namespace servodrift::system
