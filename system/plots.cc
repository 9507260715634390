#include "system/plots.h"

#include "common/output_files.h"
#include "common/units.h"
#include "system/system_stage.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace servodrift::system
{
  namespace
  {
    std::string data_files(const SystemResults &r, const std::string &dir, const ValveDescription &valve)
    {
      const auto &m = r.drift_map;
      // surfaces: one scan per temperature, separated by blank lines (gnuplot grid format)
      std::ostringstream surface;
      surface << "# temperature[degC] deviation_angle[deg] spool_displacement_deviation[um] "
                 "brake_pressure_deviation[kPa] null_shift_current_of_rated[%]\n";
      for (std::size_t t = 0; t < m.temperatures.size(); ++t)
        {
          for (std::size_t a = 0; a < m.deviation_angles.size(); ++a)
            {
              const auto &p = m.at(t, a);
              surface << format_cell(p.temperature) << ' ' << format_cell(p.deviation_angle / units::degree) << ' '
                      << format_cell(p.spool_displacement_deviation * 1e6) << ' '
                      << format_cell(p.brake_pressure_deviation * 1e-3) << ' '
                      << (p.null_shift_current ? format_cell(100 * *p.null_shift_current / valve.operating.rated_current) : "NaN")
                      << "\n";
            }
          surface << "\n";
        }
      write_file_atomically(dir + "/drift_surface.dat", surface.str());

      // lines: one block per selected angle (gnuplot `index')
      std::ostringstream lines;
      lines << "# blocks by deviation angle; temperature[degC] spool_displacement_deviation[um] "
               "brake_pressure_deviation[kPa] null_shift_current_of_rated[%] own_drift_removed[kPa]\n";
      std::string titles;
      for (std::size_t a : representative_indices(m.deviation_angles.size()))
        {
          const std::string title = format_cell(m.deviation_angles[a] / units::degree) + " deg";
          titles += (titles.empty() ? "" : " ") + std::string("'") + title + "'";
          lines << "# theta_d = " << title << "\n";
          for (std::size_t t = 0; t < m.temperatures.size(); ++t)
            {
              const auto &p = m.at(t, a);
              lines << format_cell(p.temperature) << ' ' << format_cell(p.spool_displacement_deviation * 1e6) << ' '
                    << format_cell(p.brake_pressure_deviation * 1e-3) << ' '
                    << (p.null_shift_current ? format_cell(100 * *p.null_shift_current / valve.operating.rated_current) : "NaN")
                    << ' ' << format_cell(p.brake_pressure_deviation_own_drift_removed * 1e-3) << "\n";
            }
          lines << "\n\n";
        }
      write_file_atomically(dir + "/drift_lines.dat", lines.str());

      // the null-shift spec's band (`Tolerances/Null-shift spec')
      std::ostringstream spec;
      spec << "# temperature[degC] allowed_null_shift_current_of_rated[%]\n";
      for (double T : m.temperatures)
        spec << format_cell(T) << ' '
             << format_cell(100 * valve.tolerances.null_shift_limit(T, valve.operating.reference_temperature)) << "\n";
      write_file_atomically(dir + "/null_shift_spec.dat", spec.str());

      // stage coefficients relative to their value at the first drift temperature
      std::ostringstream coefficients;
      const auto &c0 = r.coefficients.front();
      coefficients << "# temperature[degC] and K_m, K_t, K_a, K_f, C_d0, C_dn relative to " << c0.temperature << " degC\n";
      for (const auto &c : r.coefficients)
        coefficients << format_cell(c.temperature) << ' '
                     << format_cell(c.motor.secant_magnetic_spring / c0.motor.secant_magnetic_spring) << ' '
                     << format_cell(c.motor.torque_constant / c0.motor.torque_constant) << ' '
                     << format_cell(c.spring_stiffness / c0.spring_stiffness) << ' '
                     << format_cell(c.flow_force_stiffness / c0.flow_force_stiffness) << ' '
                     << format_cell(c.orifice_discharge / c0.orifice_discharge) << ' '
                     << format_cell(c.nozzle_discharge / c0.nozzle_discharge) << "\n";
      write_file_atomically(dir + "/stage_coefficients.dat", coefficients.str());
      return titles;
    }

    std::vector<Plot> plot_bodies(const std::string &titles, const DriftMap &m)
    {
      const std::string convention = m.nulled_at_reference ? "nulled at reference" : "as assembled";
      const std::string surface_common =
        "set xlabel 'temperature [degC]'\nset ylabel 'deviation angle [deg]'\nset pm3d at s\nset hidden3d\n"
        "set palette rgbformulae 33,13,10\nset view 60,35\n";
      const std::string line_common =
        "set xlabel 'temperature [degC]'\nset grid\nset key outside right\ntitles = \"" + titles + "\"\n";
      return {
        {"drift_spool_displacement_surface",
         surface_common + "set zlabel 'delta x_v [um]' rotate\nset title 'Spool displacement deviation at i = 0 (" +
           convention + ")'\nsplot 'drift_surface.dat' using 1:2:3 with lines notitle\n"},
        {"drift_brake_pressure_surface",
         surface_common + "set zlabel 'delta p_B [kPa]' rotate\nset title 'Brake pressure deviation at rated current (" +
           convention + ")'\nsplot 'drift_surface.dat' using 1:2:4 with lines notitle\n"},
        {"drift_spool_displacement_lines",
         line_common + "set ylabel 'delta x_v [um]'\nset title 'Spool displacement deviation at i = 0'\n"
                       "plot for [k=0:words(titles)-1] 'drift_lines.dat' index k using 1:2 with linespoints title "
                       "'theta_d = '.word(titles,k+1)\n"},
        {"drift_brake_pressure_lines",
         line_common + "set ylabel 'delta p_B [kPa]'\nset title 'Brake pressure deviation at rated current'\n"
                       "plot for [k=0:words(titles)-1] 'drift_lines.dat' index k using 1:3 with linespoints title "
                       "'theta_d = '.word(titles,k+1)\n"},
        {"null_shift_current_lines",
         line_common + "set ylabel 'null-shift current [% of rated]'\nset title 'Current that restores null'\n"
                       "plot for [k=0:words(titles)-1] 'drift_lines.dat' index k using 1:4 with linespoints title "
                       "'theta_d = '.word(titles,k+1), 'null_shift_spec.dat' using 1:2 with lines lw 2 lc 'red' "
                       "title 'spec', '' using 1:(-$2) with lines lw 2 lc 'red' notitle\n"},
        {"stage_coefficients",
         "set xlabel 'temperature [degC]'\nset ylabel 'relative to the first temperature'\nset grid\nset key outside right\n"
         "set title 'Stage coefficients vs temperature'\n"
         "plot 'stage_coefficients.dat' using 1:2 w lp t 'K_m (secant)', '' using 1:3 w lp t 'K_t', '' using 1:4 w lp t "
         "'K_a', '' using 1:5 w lp t 'K_f', '' using 1:6 w lp t 'C_{d0}', '' using 1:7 w lp t 'C_{dn}'\n"}};
    }
  } // namespace

  std::vector<std::size_t> representative_indices(std::size_t n)
  {
    std::vector<std::size_t> out;
    for (std::size_t k : {std::size_t(0), n / 4, n / 2, (3 * n) / 4, n - 1})
      if (k < n && (out.empty() || out.back() != k))
        out.push_back(k);
    return out;
  }

  void render_plots(const ValveDescription &valve, const std::vector<Plot> &plots, const std::string &dir,
                    PlotFiles &files)
  {
    const bool have_gnuplot = std::system("gnuplot --version > /dev/null 2>&1") == 0;
    if (!have_gnuplot)
      files.problem = "gnuplot was not found: the .dat data and .gp scripts are in system/plots/ (run `gnuplot "
                      "<name>.gp' there)";
    for (const auto &plot : plots)
      for (const auto &format : valve.output.plot_formats)
        {
          const std::string terminal = format == "png" ? "pngcairo size 960,680 font 'sans,10'" : "svg size 960,680 dynamic";
          const std::string image = plot.name + "." + format;
          write_file_atomically(dir + "/" + plot.name + "." + format + ".gp",
                                "# gnuplot script written by servodrift; run in this directory\nset terminal " + terminal +
                                  "\nif (!exists('outfile')) outfile = '" + image + "'\nset output outfile\n" + plot.body + "set output\n");
          if (!have_gnuplot)
            continue;
          const std::string command = "cd '" + dir + "' && gnuplot -e \"outfile='" + image + ".tmp'\" '" + plot.name + "." + format + ".gp' > /dev/null 2>&1";
          if (std::system(command.c_str()) == 0)
            {
              install_file(dir + "/" + image + ".tmp", dir + "/" + image);
              files.images.push_back("system/plots/" + image);
            }
          else
            {
              std::remove((dir + "/" + image + ".tmp").c_str());
              files.problem = "gnuplot failed on system/plots/" + plot.name + "." + format + ".gp";
            }
        }
  }

  PlotFiles write_plots(const ValveDescription &valve, const SystemResults &results, const std::string &dir)
  {
    PlotFiles files;
    if (!valve.output.plots)
      {
        files.problem = "plots switched off (`Output/Plots')";
        return files;
      }
    prepare_output_directory(dir);
    const std::string titles = data_files(results, dir, valve);
    render_plots(valve, plot_bodies(titles, results.drift_map), dir, files);
    return files;
  }
} // namespace servodrift::system
