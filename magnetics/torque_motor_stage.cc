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
#include <array>
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

    constexpr std::size_t summary_length = 11; // a summary row; table rows have 6 entries

    /// Which grid cases a temperature's field sweep solves, and which it takes from their mirror image.
    /// The motor is symmetric about its centre plane x = 0: the mesh is its right half mirrored, the
    /// magnets' field is odd in x and the coils' even (method.md, torque motor, field level). The
    /// mirror image of the case (theta, i) is therefore the case (-theta, -i) with every torque
    /// negated, T(-theta, -i) = -T(theta, i), by both methods: where the grid holds both, one is
    /// solved, the one with theta > 0 (or theta = 0 and i > 0), and the other mirrored. A case whose
    /// field is written to a VTU file is always solved.
    struct MirrorPlan
    {
      static constexpr std::size_t solved = std::size_t(-1);
      std::vector<std::size_t> image_of; ///< per case a * n_i + c: the solved case it mirrors, or `solved'
      std::size_t n_solved = 0;
    };

    MirrorPlan mirror_plan(const ValveDescription &valve, double T)
    {
      const auto &angles = valve.sweeps.motor_angles, &currents = valve.sweeps.motor_currents;
      const std::size_t n_a = angles.size(), n_i = currents.size();
      const auto index_of = [](const std::vector<double> &grid, double x) {
        // the grids hold values as parsed: a mirrored entry is the exact negative of its partner
        const auto it = std::find(grid.begin(), grid.end(), -x);
        return it == grid.end() ? MirrorPlan::solved : std::size_t(it - grid.begin());
      };
      MirrorPlan plan;
      plan.image_of.assign(n_a * n_i, MirrorPlan::solved);
      for (std::size_t a = 0; a < n_a; ++a)
        for (std::size_t c = 0; c < n_i; ++c)
          {
            const double theta = angles[a], i = currents[c];
            const bool mirrored_half = theta < 0 || (theta == 0 && i < 0);
            const std::size_t a_m = index_of(angles, theta), c_m = index_of(currents, i);
            if (mirrored_half && a_m != MirrorPlan::solved && c_m != MirrorPlan::solved && !wanted(valve, T, theta, i))
              plan.image_of[a * n_i + c] = a_m * n_i + c_m;
            else
              ++plan.n_solved;
          }
      return plan;
    }

    /// One temperature of the field sweep: every angle and current on one mesh, each solve starting
    /// from its neighbours' solutions (currents outer, angles back and forth); the mirror images of
    /// solved cases are not solved again (MirrorPlan). Each case is solved again on the error mesh
    /// (error_mesh_resolution_ratio): the table's torque_error is the torque minus the error mesh's.
    CaseRows field_case(const ValveDescription &valve, double T)
    {
      const auto start = std::chrono::steady_clock::now();
      const auto &sw = valve.sweeps;
      TorqueMotorFieldModel model(valve, T);
      TorqueMotorFieldModel error_mesh(valve, T, error_mesh_resolution_ratio * valve.torque_motor.field_mesh_resolution);
      const double error_tolerance = error_mesh_tolerance(valve);
      const std::size_t n_a = sw.motor_angles.size(), n_i = sw.motor_currents.size();
      const MirrorPlan plan = mirror_plan(valve, T);
      double newton = 0, gap_flux = std::nan(""), armature_flux = std::nan("");
      std::vector<std::array<double, 2>> raw(n_a * n_i);
      for (std::size_t c = 0; c < n_i; ++c)
        for (std::size_t k = 0; k < n_a; ++k)
          {
            const std::size_t a = c % 2 ? n_a - 1 - k : k;
            if (plan.image_of[a * n_i + c] != MirrorPlan::solved)
              continue;
            const double theta = sw.motor_angles[a], i = sw.motor_currents[c];
            const FieldTorque t = model.torque(theta, i);
            newton += t.newton.iterations;
            raw[a * n_i + c] = {t.stress_tensor, error_mesh.torque(theta, i, false, error_tolerance).stress_tensor};
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
      for (std::size_t k = 0; k < n_a * n_i; ++k)
        if (plan.image_of[k] != MirrorPlan::solved)
          raw[k] = {-raw[plan.image_of[k]][0], -raw[plan.image_of[k]][1]};
      // secant K_m of the field (C1) for the paper preset's E25 correction
      double secant = 0;
      if (valve.torque_motor.paper_magnetic_spring)
        {
          const double tenth = 0.1 * units::degree;
          secant = model.torque(tenth, 0.0).stress_tensor / tenth;
        }
      const PaperMagneticSpring paper(valve, T, secant);
      CaseRows rows;
      for (std::size_t a = 0; a < n_a; ++a)
        for (std::size_t c = 0; c < n_i; ++c)
          {
            const double theta = sw.motor_angles[a];
            const double torque = raw[a * n_i + c][0], on_error_mesh = raw[a * n_i + c][1];
            rows.push_back(
              {T, theta, sw.motor_currents[c], torque + paper.correction * theta, torque - on_error_mesh, paper.flag});
          }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      rows.push_back({T, double(model.n_dofs()), double(model.problem().n_cells()), gap_flux, armature_flux, newton,
                      double(n_a * n_i), double(plan.n_solved), double(error_mesh.n_dofs()), seconds, 0.0});
      return rows;
    }

    void write_field_summary(const ValveDescription &valve, const CaseRows &summary)
    {
      CsvDocument doc;
      doc.comments = {"servodrift-output magnetics_field_summary",
                      "field-level torque motor per temperature: mesh size, working-gap flux density and largest "
                      "armature flux density at theta = 0, i = 0, Newton iterations (with chord steps), the table's cases "
                      "and those solved (the others are mirror images: T(-theta, -i) = -T(theta, i)), the unknowns of "
                      "the error mesh (half the resolution: the table's torque_error is the torque's change there) and time",
                      "producer " + producer_string("magnetics/field"), "parameters-sha256 " + valve.parameters_sha256};
      doc.columns = {"temperature[degC]", "unknowns[1]", "cells[1]", "mean_gap_flux_density[T]",
                     "max_armature_flux_density[T]", "newton_iterations[1]", "cases[1]", "solved_cases[1]",
                     "error_mesh_unknowns[1]", "wall_time[s]"};
      for (const auto &r : summary)
        doc.rows.push_back({format_cell(r[0]), format_cell(r[1]), format_cell(r[2]),
                            std::isfinite(r[3]) ? format_cell(r[3]) : "", std::isfinite(r[4]) ? format_cell(r[4]) : "",
                            format_cell(r[5]), format_cell(r[6]), format_cell(r[7]), format_cell(r[8]),
                            format_cell(r[9])});
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
