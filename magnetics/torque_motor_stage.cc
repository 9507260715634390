#include "magnetics/torque_motor_stage.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/units.h"
#include "common/version.h"
#include "common/vtu_output.h"
#include "common/torque_motor_circuit.h"
#include "magnetics/torque_motor_field.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace servodrift::magnetics
{
  namespace
  {
    /// Paper preset (D2): the linear magnetic spring follows E25 instead of the model's secant K_m
    /// (C1); the nonlinear and current-driven parts stay the model's. Clamped outside 40..120 degC.
    struct PaperMagneticSpring
    {
      double correction = 0; ///< K_m,E25(T) - K_m,secant(T) [N*m/rad]
      double flag = flags::computed;
      PaperMagneticSpring(const ValveDescription &valve, double T, double secant)
      {
        if (!valve.torque_motor.paper_magnetic_spring)
          return;
        const double T_fit = std::clamp(T, 40.0, 120.0); // E25 was fitted over 40..120 degC only (C6)
        correction = (11.61 - 0.004837 * T_fit) - secant; // E25
        if (T_fit != T)
          flag = flags::clamped;
      }
    };

    CaseRows reduced_order_case(const ValveDescription &valve, double T)
    {
      const auto &sw = valve.sweeps;
      const TorqueMotorCircuit circuit(valve, T);
      const double tenth = 0.1 * units::degree;
      const PaperMagneticSpring paper(valve, T, circuit.torque(tenth, 0) / tenth);
      CaseRows rows;
      for (double theta : sw.motor_angles)
        for (double i : sw.motor_currents)
          // the circuit is solved exactly: no discretisation error to report
          rows.push_back({T, theta, i, circuit.torque(theta, i) + paper.correction * theta, 0.0, paper.flag});
      return rows;
    }

    std::string field_file_name(double T, double theta, double i)
    {
      char b[128];
      std::snprintf(b, sizeof(b), "field_T%g_angle%g_current%g.vtu", T, theta / units::degree, i);
      return b;
    }

    bool wanted(const ValveDescription &valve, double T, double theta, double i)
    {
      if (valve.output.all_magnetics_fields)
        return true;
      for (const auto &c : valve.output.magnetics_field_cases)
        if (std::abs(c[0] - T) < 1e-9 && std::abs(c[1] - theta) < 1e-9 * units::degree && std::abs(c[2] - i) < 1e-12)
          return true;
      return false;
    }

    constexpr std::size_t summary_length = 9; // a summary row; table rows have 6 entries

    /// One temperature of the field sweep: every angle and current on one mesh, each solve starting
    /// from its neighbour's solution (currents outer, angles back and forth).
    CaseRows field_case(const ValveDescription &valve, double T)
    {
      const auto start = std::chrono::steady_clock::now();
      const auto &sw = valve.sweeps;
      TorqueMotorFieldModel model(valve, T);
      const std::size_t n_a = sw.motor_angles.size(), n_i = sw.motor_currents.size();
      double newton = 0, gap_flux = std::nan(""), armature_flux = std::nan("");
      std::vector<std::vector<double>> raw(n_a * n_i);
      for (std::size_t c = 0; c < n_i; ++c)
        for (std::size_t k = 0; k < n_a; ++k)
          {
            const std::size_t a = c % 2 ? n_a - 1 - k : k;
            const double theta = sw.motor_angles[a], i = sw.motor_currents[c];
            const FieldTorque t = model.torque(theta, i, true);
            newton += t.newton.iterations;
            raw[a * n_i + c] = {t.stress_tensor, t.virtual_work};
            if (theta == 0 && i == 0)
              {
                gap_flux = model.mean_gap_flux_density();
                armature_flux = model.max_armature_flux_density();
              }
            if (wanted(valve, T, theta, i))
              {
                const std::string dir = valve.output.directory + "/magnetics";
                prepare_output_directory(dir);
                model.problem().write_vtu(dir + "/" + field_file_name(T, theta, i));
              }
          }
      // secant K_m of the field (C1) for the paper preset's E25 correction
      double secant = 0;
      if (valve.torque_motor.paper_magnetic_spring)
        {
          const double tenth = 0.1 * units::degree;
          secant = model.torque(tenth, 0.0, false).stress_tensor / tenth;
        }
      const PaperMagneticSpring paper(valve, T, secant);
      CaseRows rows;
      for (std::size_t a = 0; a < n_a; ++a)
        for (std::size_t c = 0; c < n_i; ++c)
          {
            const double theta = sw.motor_angles[a];
            const double mst = raw[a * n_i + c][0], vw = raw[a * n_i + c][1];
            // the table's torque is the stress tensor's; its error column the difference of the methods
            rows.push_back({T, theta, sw.motor_currents[c], mst + paper.correction * theta, vw - mst, paper.flag});
          }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      rows.push_back({T, double(model.n_dofs()), double(model.problem().n_cells()), gap_flux, armature_flux, newton,
                      double(n_a * n_i), seconds, 0.0});
      return rows;
    }

    void write_field_summary(const ValveDescription &valve, const CaseRows &summary)
    {
      CsvDocument doc;
      doc.comments = {"servodrift-output magnetics_field_summary",
                      "field-level torque motor per temperature: mesh size, working-gap flux density and largest "
                      "armature flux density at theta = 0, i = 0, Newton iterations (with chord steps) and time",
                      "producer " + producer_string("magnetics/field"), "parameters-sha256 " + valve.parameters_sha256};
      doc.columns = {"temperature[degC]", "unknowns[1]", "cells[1]", "mean_gap_flux_density[T]",
                     "max_armature_flux_density[T]", "newton_iterations[1]", "cases[1]", "wall_time[s]"};
      for (const auto &r : summary)
        doc.rows.push_back({format_cell(r[0]), format_cell(r[1]), format_cell(r[2]),
                            std::isfinite(r[3]) ? format_cell(r[3]) : "", std::isfinite(r[4]) ? format_cell(r[4]) : "",
                            format_cell(r[5]), format_cell(r[6]), format_cell(r[7])});
      const std::string dir = valve.output.directory + "/magnetics";
      prepare_output_directory(dir);
      write_file_atomically(dir + "/field_summary.csv", doc.text());

      // ParaView collection of the VTU files written
      std::vector<std::pair<double, std::string>> datasets;
      for (double T : valve.sweeps.table_temperatures)
        for (double theta : valve.sweeps.motor_angles)
          for (double i : valve.sweeps.motor_currents)
            if (wanted(valve, T, theta, i))
              datasets.emplace_back(datasets.size(), field_file_name(T, theta, i));
      if (!datasets.empty())
        write_pvd_atomically(dir + "/fields.pvd", datasets);
    }
  } // namespace

  Table compute_torque_motor_table(const ValveDescription &valve)
  {
    const auto &T = valve.sweeps.table_temperatures;
    const bool field = valve.torque_motor.model_level == ModelLevel::field;
    Table table(schemas::torque_motor);
    const CaseRows rows = run_sweep(
      std::string("magnetics (") + (field ? "field" : "reduced-order") + ")", T.size(),
      [&](std::size_t k) { return field ? field_case(valve, T[k]) : reduced_order_case(valve, T[k]); },
      valve.output.progress);
    CaseRows summary;
    for (const auto &r : rows)
      (r.size() == summary_length ? summary : table.rows).push_back(r);
    if (field)
      on_rank_zero([&] { write_field_summary(valve, summary); });
    return table;
  }

  void run(const ValveDescription &valve)
  {
    Table table = compute_torque_motor_table(valve);
    write_table(valve, table, "magnetics/" + to_string(valve.torque_motor.model_level));
  }
} // namespace servodrift::magnetics
