// Studies of the field-level torque motor: C10 calibration of the equivalent magnet blocks, mesh
// convergence and the position of the outer boundary.
#include "common/csv.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/units.h"
#include "common/version.h"
#include "common/torque_motor_circuit.h"
#include "magnetics/torque_motor_field.h"
#include "magnetics/torque_motor_stage.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace servodrift::magnetics
{
  namespace
  {
    struct Coefficients
    {
      double torque_tenth;  ///< T(0.1 deg, 0) [N*m]
      double secant_spring; ///< K_m = T(0.1 deg, 0)/0.1 deg (C1) [N*m/rad]
      double torque_constant; ///< K_t = (T(0, i_r) - T(0, -i_r))/(2 i_r) [N*m/A]
      double gap_flux;      ///< mean working-gap |B_y| at theta = 0, i = 0 [T]
      unsigned int dofs, cells;
    };

    Coefficients field_coefficients(const ValveDescription &valve, double T, double resolution,
                                    unsigned int refinements = 0)
    {
      TorqueMotorFieldModel model(valve, T, resolution, refinements);
      const double tenth = 0.1 * units::degree, i_r = valve.operating.rated_current;
      Coefficients c;
      model.torque(0, 0, false);
      c.gap_flux = model.mean_gap_flux_density();
      c.torque_tenth = model.torque(tenth, 0, false).stress_tensor;
      c.secant_spring = c.torque_tenth / tenth;
      c.torque_constant = (model.torque(0, i_r, false).stress_tensor - model.torque(0, -i_r, false).stress_tensor) / (2 * i_r);
      c.dofs = model.n_dofs();
      c.cells = model.problem().n_cells();
      return c;
    }

    Coefficients circuit_coefficients(const ValveDescription &valve, double T)
    {
      const TorqueMotorCircuit circuit(valve, T);
      const double tenth = 0.1 * units::degree, i_r = valve.operating.rated_current;
      Coefficients c{};
      c.torque_tenth = circuit.torque(tenth, 0);
      c.secant_spring = c.torque_tenth / tenth;
      c.torque_constant = (circuit.torque(0, i_r) - circuit.torque(0, -i_r)) / (2 * i_r);
      c.gap_flux = circuit.solve(0, 0).gap_flux[0] / circuit.gap_area();
      return c;
    }

    ValveDescription with_magnet_width(const ValveDescription &valve, double width)
    {
      ValveDescription v = valve;
      v.torque_motor.field_magnet_width = width;
      return v;
    }

    void say(const std::string &s)
    {
      if (mpi_rank() == 0)
        std::cout << s << std::flush;
    }

    std::string f(double v, int digits = 6)
    {
      char b[48];
      std::snprintf(b, sizeof(b), "%.*g", digits, v);
      return b;
    }
  } // namespace

  void calibrate(const ValveDescription &valve)
  {
    const double T0 = valve.operating.reference_temperature;
    const Coefficients circuit = circuit_coefficients(valve, T0);
    const double target = circuit.gap_flux;
    say("C10 calibration at " + f(T0) + " degC: target mean gap flux density (circuit) " + f(target) + " T\n");

    // Secant iterations on the block width for B_gap(w) = target (B_gap grows monotonically with w)
    CsvDocument doc;
    doc.comments = {"servodrift-output magnetics_calibration",
                    "C10: equivalent in-plane magnet width vs the field model's mean working-gap flux density at "
                    "theta = 0, i = 0, T0; target = the circuit's B_g",
                    "producer " + producer_string("magnetics/field"), "parameters-sha256 " + valve.parameters_sha256};
    doc.columns = {"iteration[1]", "magnet_width[m]", "mean_gap_flux_density[T]", "target[T]"};
    double w0 = valve.torque_motor.field_magnet_width;
    double b0 = field_coefficients(with_magnet_width(valve, w0), T0, 0).gap_flux;
    doc.rows.push_back({"0", format_cell(w0), format_cell(b0), format_cell(target)});
    say("  width " + f(w0 * 1e3) + " mm: " + f(b0) + " T (uncalibrated)\n");
    double w1 = w0 * target / b0, b1 = 0;
    for (int k = 1; k <= 12; ++k)
      {
        b1 = field_coefficients(with_magnet_width(valve, w1), T0, 0).gap_flux;
        doc.rows.push_back({std::to_string(k), format_cell(w1), format_cell(b1), format_cell(target)});
        say("  width " + f(w1 * 1e3) + " mm: " + f(b1) + " T\n");
        if (std::abs(b1 - target) < 1e-5 * target)
          break;
        const double w2 = w1 + (target - b1) * (w1 - w0) / (b1 - b0);
        w0 = w1, b0 = b1, w1 = w2;
      }
    const Coefficients before = field_coefficients(valve, T0, 0);
    const Coefficients after = field_coefficients(with_magnet_width(valve, w1), T0, 0);
    on_rank_zero([&] {
      const std::string dir = valve.output.directory + "/magnetics";
      prepare_output_directory(dir);
      write_file_atomically(dir + "/calibration.csv", doc.text());
    });
    std::ostringstream s;
    s << "\n  quantity at " << f(T0) << " degC        circuit    field (" << f(valve.torque_motor.field_magnet_width * 1e3)
      << " mm)    field (" << f(w1 * 1e3) << " mm)\n"
      << "  mean gap B [T]           " << f(circuit.gap_flux) << "   " << f(before.gap_flux) << "   " << f(after.gap_flux) << "\n"
      << "  T(0.1 deg) [N*m]         " << f(circuit.torque_tenth) << "   " << f(before.torque_tenth) << "   "
      << f(after.torque_tenth) << "\n"
      << "  K_m secant [N*m/rad]     " << f(circuit.secant_spring) << "   " << f(before.secant_spring) << "   "
      << f(after.secant_spring) << "\n"
      << "  K_t [N*m/A]              " << f(circuit.torque_constant) << "   " << f(before.torque_constant) << "   "
      << f(after.torque_constant) << "\n"
      << "\ncalibrated: set `Torque motor/Field magnet width' = " << f(w1, 6) << " (m)\n";
    say(s.str());
  }

  void convergence_study(const ValveDescription &valve)
  {
    const double T0 = valve.operating.reference_temperature;
    // Nested meshes: the default mesh refined globally 0, 1, 2 times (h, h/2, h/4)
    const std::vector<unsigned int> levels{0, 1, 2};
    std::vector<Coefficients> c;
    say("mesh convergence at " + f(T0) + " degC, element degree " + std::to_string(valve.torque_motor.field_element_degree) +
        ", the default mesh refined globally\n  refinements  cells  unknowns  T(0.1 deg) [N*m]  K_m [N*m/rad]  "
        "K_t [N*m/A]\n");
    for (unsigned int r : levels)
      {
        c.push_back(field_coefficients(valve, T0, 0, r));
        say("  " + f(r) + "  " + std::to_string(c.back().cells) + "  " + std::to_string(c.back().dofs) + "  " +
            f(c.back().torque_tenth, 8) + "  " + f(c.back().secant_spring, 8) + "  " + f(c.back().torque_constant, 8) +
            "\n");
      }
    // observed order from the three finest (resolution doubles: h halves), Richardson estimate
    auto order = [&](double (*q)(const Coefficients &)) {
      const std::size_t n = c.size();
      return std::log(std::abs(q(c[n - 3]) - q(c[n - 2])) / std::abs(q(c[n - 2]) - q(c[n - 1]))) / std::log(2.0);
    };
    const double p_T = order([](const Coefficients &x) { return x.torque_tenth; });
    const double p_m = order([](const Coefficients &x) { return x.secant_spring; });
    const double p_t = order([](const Coefficients &x) { return x.torque_constant; });
    CsvDocument doc;
    doc.comments = {"servodrift-output magnetics_convergence",
                    "field-level torque motor at T0 on nested meshes (the default mesh refined globally); observed "
                    "order from the three finest: T(0.1 deg) " + f(p_T, 3) + ", K_m " + f(p_m, 3) + ", K_t " + f(p_t, 3),
                    "producer " + producer_string("magnetics/field"), "parameters-sha256 " + valve.parameters_sha256};
    doc.columns = {"refinements[1]", "cells[1]", "unknowns[1]", "torque_at_0.1deg[N*m]", "magnetic_spring_secant[N*m/rad]",
                   "torque_constant[N*m/A]", "change_from_previous[1]"};
    for (std::size_t k = 0; k < c.size(); ++k)
      doc.rows.push_back({format_cell(levels[k]), format_cell(c[k].cells), format_cell(c[k].dofs),
                          format_cell(c[k].torque_tenth), format_cell(c[k].secant_spring), format_cell(c[k].torque_constant),
                          k ? format_cell(c[k].torque_tenth / c[k - 1].torque_tenth - 1) : ""});
    say("  observed order (three finest): T(0.1 deg) " + f(p_T, 3) + ", K_m " + f(p_m, 3) + ", K_t " + f(p_t, 3) + "\n");

    // outer boundary: A_z = 0 on a circle of radius R, 1.5 R and 2 R
    CsvDocument boundary;
    boundary.comments = {"servodrift-output magnetics_boundary_study",
                         "field-level torque motor at T0: sensitivity of T(0.1 deg) and K_t to the radius of the outer "
                         "boundary (A_z = 0)",
                         "producer " + producer_string("magnetics/field"), "parameters-sha256 " + valve.parameters_sha256};
    boundary.columns = {"air_boundary_radius[m]", "torque_at_0.1deg[N*m]", "torque_constant[N*m/A]", "change_from_default[1]"};
    say("outer boundary at " + f(T0) + " degC\n  radius [m]  T(0.1 deg) [N*m]  K_t [N*m/A]  change\n");
    double reference = 0;
    for (double factor : {1.0, 1.5, 2.0})
      {
        ValveDescription v = valve;
        v.torque_motor.air_boundary_radius *= factor;
        const Coefficients b = field_coefficients(v, T0, 0);
        if (factor == 1.0)
          reference = b.torque_tenth;
        boundary.rows.push_back({format_cell(v.torque_motor.air_boundary_radius), format_cell(b.torque_tenth),
                                 format_cell(b.torque_constant), format_cell(b.torque_tenth / reference - 1)});
        say("  " + f(v.torque_motor.air_boundary_radius) + "  " + f(b.torque_tenth, 8) + "  " + f(b.torque_constant, 8) +
            "  " + f(b.torque_tenth / reference - 1, 3) + "\n");
      }
    on_rank_zero([&] {
      const std::string dir = valve.output.directory + "/magnetics";
      prepare_output_directory(dir);
      write_file_atomically(dir + "/convergence.csv", doc.text());
      write_file_atomically(dir + "/boundary_study.csv", boundary.text());
    });
  }
} // namespace servodrift::magnetics
