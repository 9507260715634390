#include "common/stage_output.h"

#include "common/error.h"
#include "common/grid_function.h"
#include "common/output_files.h"
#include "common/sweep.h"
#include "common/table_coefficients.h"
#include "common/units.h"
#include "common/version.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace servodrift
{
  std::string tables_directory(const ValveDescription &valve)
  {
    return valve.output.directory + "/tables";
  }

  std::string table_path(const ValveDescription &valve, const std::string &name)
  {
    return tables_directory(valve) + "/" + name + ".csv";
  }

  void mpi_barrier()
  {
    if (dealii::Utilities::MPI::job_supports_mpi() && mpi_size() > 1)
      MPI_Barrier(MPI_COMM_WORLD);
  }

  void on_rank_zero(const std::function<void()> &write)
  {
    std::string error;
    if (mpi_rank() == 0)
      try
        {
          write();
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    if (mpi_size() > 1)
      error = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  void write_table(const ValveDescription &valve, Table &table, const std::string &stage_and_level,
                   const std::string &variant)
  {
    table.producer = producer_string(stage_and_level);
    table.parameters_sha256 = valve.parameters_sha256;
    on_rank_zero([&] {
      prepare_output_directory(tables_directory(valve));
      table.write(table_path(valve, table.name() + (variant.empty() ? "" : "." + variant)));
    });
  }

  void write_parameters_file(const ValveDescription &valve)
  {
    on_rank_zero([&] {
      prepare_output_directory(valve.output.directory);
      write_file_atomically(valve.output.directory + "/parameters.prm",
                            "# " + producer_string("parameters as used; source: " + valve.source) + "\n" +
                              valve.parameter_file);
    });
  }

  namespace
  {
    std::vector<std::vector<double>> axes_of(const Table &t, std::initializer_list<const char *> names,
                                             const std::function<bool(const std::vector<double> &)> &keep)
    {
      std::vector<std::size_t> c;
      for (const char *n : names)
        c.push_back(t.column_index(n));
      std::vector<std::vector<double>> out;
      for (const auto &r : t.rows)
        if (keep(r))
          {
            std::vector<double> p;
            for (auto k : c)
              p.push_back(r[k]);
            out.push_back(p);
          }
      return out;
    }

    std::vector<double> values_of(const Table &t, const char *name, const std::function<bool(const std::vector<double> &)> &keep)
    {
      const auto c = t.column_index(name);
      std::vector<double> out;
      for (const auto &r : t.rows)
        if (keep(r))
          out.push_back(r[c]);
      return out;
    }

    std::vector<std::string> headers(const Table &t, std::initializer_list<const char *> names)
    {
      std::vector<std::string> out;
      for (const char *n : names)
        out.push_back(t.schema().columns[t.column_index(n)].header());
      return out;
    }

    PolynomialFit general_fit(const Table &t, const char *response, std::initializer_list<const char *> variables,
                              std::vector<int> degrees, const std::function<bool(const std::vector<double> &)> &keep)
    {
      // A variable with n distinct values in the table supports powers up to n - 1 only
      const auto points = axes_of(t, variables, keep);
      std::string capped;
      for (std::size_t j = 0; j < degrees.size(); ++j)
        {
          std::vector<double> values;
          for (const auto &p : points)
            values.push_back(p[j]);
          std::sort(values.begin(), values.end());
          const int distinct = static_cast<int>(std::unique(values.begin(), values.end()) - values.begin());
          if (degrees[j] > distinct - 1)
            {
              degrees[j] = std::max(0, distinct - 1);
              capped += std::string(capped.empty() ? "" : ", ") + *(variables.begin() + j) + " to " + std::to_string(degrees[j]);
            }
        }
      PolynomialFit f = fit_polynomial(points, values_of(t, response, keep), full_polynomial_exponents(degrees));
      if (!capped.empty())
        f.note = "degree capped by the table's points: " + capped;
      f.name = std::string("full polynomial ") + response;
      f.source = t.name() + ".csv";
      f.response = t.schema().columns[t.column_index(response)].header();
      f.variables = headers(t, variables);
      return f;
    }
  } // namespace

  std::vector<PolynomialFit> fits_of_table(const Table &t, const ValveDescription &valve)
  {
    std::vector<PolynomialFit> fits;
    const auto all = [](const std::vector<double> &) { return true; };
    if (t.name() == "torque_motor")
      {
        // E25: T_e = (K_m0 + K_mT T) theta, fitted to the secant K_m at 0.1 deg (C1) of each
        // temperature; and K_t(T) the same way
        const GridFunction torque = GridFunction::from_table(t, "torque_motor", "torque");
        std::vector<std::vector<double>> T;
        std::vector<TorqueMotorCoefficients> c;
        for (double temperature : torque.axis(0))
          {
            T.push_back({temperature});
            c.push_back(torque_motor_coefficients(torque, temperature));
          }
        auto linear_in_T = [&](const char *name, const char *response, double TorqueMotorCoefficients::*member,
                               const char *note) {
          std::vector<double> values;
          for (const auto &k : c)
            values.push_back(k.*member);
          PolynomialFit f = fit_polynomial(T, values, {{0}, {1}});
          f.name = name;
          f.source = "torque_motor.csv";
          f.response = response;
          f.variables = {"temperature[degC]"};
          f.note = note;
          fits.push_back(f);
        };
        if (T.size() >= 2)
          {
            linear_in_T("E25 magnetic spring K_m(T) = K_m0 + K_mT T", "K_m[N*m/rad]",
                        &TorqueMotorCoefficients::secant_magnetic_spring,
                        "secant K_m = T(0.1 deg, i = 0)/(0.1 deg) at each table temperature (C1); paper: K_m0 = 11.61, "
                        "K_mT = -0.004837");
            linear_in_T("torque constant K_t(T) = K_t0 + K_tT T", "K_t[N*m/A]", &TorqueMotorCoefficients::torque_constant,
                        "K_t = dT/di at theta = 0, i = 0 (Richardson-extrapolated central differences) at each table "
                        "temperature");
          }
        fits.push_back(general_fit(t, "torque", {"temperature", "angle", "current"}, valve.fits.torque_motor_degrees, all));
      }
    else if (t.name() == "spring_tube")
      fits.push_back(general_fit(t, "stiffness", {"temperature"}, valve.fits.spring_tube_degrees, all));
    else if (t.name() == "fixed_orifice")
      {
        // E26: C_d0 = c1 Re^3 + c2 Re^2 + c3 Re + c4 over the rows with flow
        const auto flowing = [&](const std::vector<double> &r) { return r[t.column_index("reynolds_number")] > 0; };
        try
          {
            PolynomialFit e26 = fit_polynomial(axes_of(t, {"reynolds_number"}, flowing),
                                               values_of(t, "discharge_coefficient", flowing), {{0}, {1}, {2}, {3}});
            e26.name = "E26 fixed-orifice discharge coefficient C_d0(Re_0), cubic";
            e26.source = "fixed_orifice.csv";
            e26.response = "discharge_coefficient[1]";
            e26.variables = {"reynolds_number[1]"};
            e26.note = "paper: c = (4.196e-13, -1.226e-8, 1.202e-4, 0.3875) for Re^3, Re^2, Re, 1";
            fits.push_back(e26);
          }
        catch (const std::invalid_argument &)
          {
            // fewer than four distinct Reynolds numbers with flow (a reduced field sweep): no E26 fit
          }
        fits.push_back(general_fit(t, "discharge_coefficient", {"temperature", "pressure_difference"},
                                   valve.fits.fixed_orifice_degrees, flowing));
      }
    else if (t.name() == "nozzle_flapper")
      {
        // E27: C_dn as a full quadratic in T and the gap, over the paper's flapper range x0 -+ 30 um,
        // at the tabulated pressure difference nearest the null value (p_s - p_r)/2.
        const double x0 = valve.pilot.null_gap;
        const double dp_null = 0.5 * (valve.operating.supply_pressure - valve.operating.return_pressure);
        const std::size_t c_dp = t.column_index("pressure_difference"), c_gap = t.column_index("gap");
        double dp_nearest = t.rows.front()[c_dp];
        for (const auto &r : t.rows)
          if (std::abs(r[c_dp] - dp_null) < std::abs(dp_nearest - dp_null))
            dp_nearest = r[c_dp];
        const auto window = [&](const std::vector<double> &r) {
          return r[c_dp] == dp_nearest && r[c_gap] > 0 && r[c_gap] >= x0 - 30e-6 && r[c_gap] <= x0 + 30e-6;
        };
        const auto flowing = [&](const std::vector<double> &r) { return r[c_gap] > 0 && r[c_dp] > 0; };
        try
          {
            PolynomialFit e27 = fit_polynomial(axes_of(t, {"temperature", "gap"}, window),
                                               values_of(t, "discharge_coefficient", window),
                                               {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}});
            e27.name = "E27 nozzle discharge coefficient C_dn(T, gap), full quadratic";
            e27.source = "nozzle_flapper.csv";
            e27.response = "discharge_coefficient[1]";
            e27.variables = {"temperature[degC]", "gap[m]"};
            e27.note = "at the tabulated pressure difference nearest (p_s - p_r)/2: " + format_cell(dp_nearest) +
                       " Pa; gaps within x0 -+ 30 um";
            fits.push_back(e27);
          }
        catch (const std::invalid_argument &)
          {
            // too few table points in the paper's window for a quadratic: no E27 fit
          }
        fits.push_back(general_fit(t, "discharge_coefficient", {"temperature", "gap", "pressure_difference"},
                                   valve.fits.nozzle_flapper_degrees, flowing));
        fits.push_back(general_fit(t, "flapper_force", {"temperature", "gap", "pressure_difference"},
                                   valve.fits.nozzle_flapper_degrees, all));
      }
    return fits;
  }

  std::vector<PolynomialFit> write_fits(const ValveDescription &valve, const std::vector<PolynomialFit> &extra)
  {
    std::vector<PolynomialFit> fits;
    for (const char *name : {"torque_motor", "spring_tube", "fixed_orifice", "nozzle_flapper"})
      {
        const std::string path = table_path(valve, name);
        if (!std::filesystem::exists(path))
          continue;
        const auto f = fits_of_table(Table::read(path, name), valve);
        fits.insert(fits.end(), f.begin(), f.end());
      }
    fits.insert(fits.end(), extra.begin(), extra.end());
    on_rank_zero([&] {
      Json list = Json::array();
      for (const auto &f : fits)
        list.push_back(f.to_json());
      Json doc = Json::object();
      doc.set("producer", producer_string("fits")).set("parameters-sha256", valve.parameters_sha256).set("fits", list);
      prepare_output_directory(tables_directory(valve));
      write_file_atomically(tables_directory(valve) + "/fits.json", doc.dump());
    });
    return fits;
  }
} // namespace servodrift
