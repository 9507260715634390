#include "structure/spring_tube_stage.h"

#include "common/csv.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/thermal_laws.h"
#include "common/version.h"
#include "common/vtu_output.h"
#include "structure/spring_tube_beam.h"
#include "structure/spring_tube_field.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace servodrift::structure
{
  SpringTubeFieldOptions field_options(const SpringTubeParameters &tube)
  {
    SpringTubeFieldOptions o;
    o.element_degree = tube.field_element_degree;
    // validate() ensures layers x resolution >= 1
    o.wall_layers = static_cast<unsigned int>(std::lround(tube.field_wall_layers * tube.field_mesh_resolution));
    o.aspect_ratio = tube.field_aspect_ratio;
    return o;
  }

  std::unique_ptr<SpringTubeField> spring_tube_field(const ValveDescription &valve, double T)
  {
    const auto &tube = valve.spring_tube;
    auto field = std::make_unique<SpringTubeField>(laws::spring_tube_geometry(tube, valve.expansion, T), // E13
                                                   laws::youngs_modulus(tube, T),                       // E12
                                                   tube.poisson_ratio, field_options(tube));
    field->run();
    return field;
  }

  double rated_armature_angle(const ValveDescription &valve)
  {
    // the flapper on its nozzle: x_f = x0 = r theta (E30)
    return valve.pilot.null_gap / valve.armature.pivot_to_nozzle_distance;
  }

  namespace
  {
    /// Columns of structure/field_summary.csv, one row per temperature.
    const std::vector<std::string> summary_columns{"temperature[degC]",
                                                   "stiffness[N*m/rad]",
                                                   "stiffness_E11[N*m/rad]",
                                                   "difference_from_E11[%]",
                                                   "compliance_moment_rotation[rad/(N*m)]",
                                                   "compliance_moment_deflection[m/(N*m)]",
                                                   "compliance_shear_deflection[m/N]",
                                                   "rated_angle[rad]",
                                                   "rated_moment[N*m]",
                                                   "beam_bending_stress[Pa]",
                                                   "von_mises_beside_ends[Pa]",
                                                   "its_radius[m]",
                                                   "its_height[m]",
                                                   "yield_margin[1]",
                                                   "von_mises_at_end_corners[Pa]",
                                                   "cells[1]",
                                                   "unknowns[1]",
                                                   "wall_time[s]"};

    std::string field_file_name(double T)
    {
      char b[64];
      std::snprintf(b, sizeof(b), "spring_tube_T%g.vtu", T);
      return b;
    }

    /// One temperature: the table row {T, K_a, flag} and the summary row (summary_columns).
    CaseRows field_case(const ValveDescription &valve, double T)
    {
      const auto start = std::chrono::steady_clock::now();
      const auto field = spring_tube_field(valve, T);
      const double K_a = field->rotational_stiffness();
      const auto C = field->compliance();
      const BeamTube beam = beam_tube(valve, T);

      // Stress at the rated deflection: the pure moment that turns the top by the rated angle.
      // Beside the ends (one wall thickness away) it is mesh-converged; at the corners where the
      // clamped or rigid faces meet the free surfaces it is singular and only reported.
      const double theta = rated_armature_angle(valve);
      const TopLoad rated{K_a * theta, 0.0};
      const auto geometry = laws::spring_tube_geometry(valve.spring_tube, valve.expansion, T);
      const double wall = 0.5 * (geometry.outer_diameter - geometry.inner_diameter);
      const StressPeak beside_ends = field->peak_stress(rated, wall);
      const StressPeak corners = field->peak_stress(rated);
      const double beam_stress = rated.moment * beam.outer_radius / beam.second_moment;

      const std::string dir = valve.output.directory + "/structure";
      prepare_output_directory(dir);
      field->write_vtu(dir + "/" + field_file_name(T), rated);

      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::vector<double> summary{T,
                                  K_a,
                                  beam.rotational_stiffness,
                                  100 * (K_a / beam.rotational_stiffness - 1),
                                  C[0][0],
                                  C[0][1],
                                  C[1][1],
                                  theta,
                                  rated.moment,
                                  beam_stress,
                                  beside_ends.von_mises,
                                  beside_ends.radius,
                                  beside_ends.height,
                                  valve.spring_tube.yield_strength / beside_ends.von_mises,
                                  corners.von_mises,
                                  double(field->n_cells()),
                                  double(field->n_dofs()),
                                  seconds};
      return {{T, K_a, flags::computed}, summary};
    }

    void write_field_summary(const ValveDescription &valve, const CaseRows &summary)
    {
      CsvDocument doc;
      doc.comments = {
        "servodrift-output structure_field_summary",
        "field-level spring tube per temperature (axisymmetric, harmonic n = 1; clamped base, rigid top): K_a = "
        "M/theta_top under a pure moment beside E11 (E I/l); the compliance of the top, (theta, delta) = C (M, V) "
        "at the centre of the top face; the stress at the rated deflection (flapper on its nozzle, x_f = x0: the "
        "pure moment that turns the top by x0/r): the beam's M R/I, the largest von Mises stress one wall "
        "thickness or more from the ends (mesh-converged; the yield margin uses it) and the one at the end "
        "corners (singular for a perfect clamp: grows with mesh refinement)",
        "producer " + producer_string("structure/field"), "parameters-sha256 " + valve.parameters_sha256};
      doc.columns = summary_columns;
      for (const auto &r : summary)
        {
          std::vector<std::string> cells;
          for (double x : r)
            cells.push_back(format_cell(x));
          doc.rows.push_back(cells);
        }
      const std::string dir = valve.output.directory + "/structure";
      prepare_output_directory(dir);
      write_file_atomically(dir + "/field_summary.csv", doc.text());

      std::vector<std::pair<double, std::string>> datasets;
      for (const auto &r : summary)
        datasets.emplace_back(r[0], field_file_name(r[0]));
      write_pvd_atomically(dir + "/spring_tube.pvd", datasets);
    }
  } // namespace

  Table compute_spring_tube_table(const ValveDescription &valve)
  {
    const auto &T = valve.sweeps.table_temperatures;
    const bool field = valve.spring_tube.model_level == ModelLevel::field;
    Table table(schemas::spring_tube);
    const CaseRows rows = run_sweep(
      std::string("structure (") + (field ? "field" : "reduced-order") + ")", T.size(),
      [&](std::size_t k) {
        return field ? field_case(valve, T[k])
                     : CaseRows{{T[k], beam_tube(valve, T[k]).rotational_stiffness, flags::computed}};
      },
      valve.output.progress);
    CaseRows summary;
    for (const auto &r : rows)
      (r.size() == summary_columns.size() ? summary : table.rows).push_back(r);
    if (field)
      on_rank_zero([&] { write_field_summary(valve, summary); });
    return table;
  }

  void run(const ValveDescription &valve)
  {
    Table table = compute_spring_tube_table(valve);
    write_table(valve, table, "structure/" + to_string(valve.spring_tube.model_level));
  }
} // namespace servodrift::structure
