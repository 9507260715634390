#include "system/dynamics_plots.h"

#include "common/output_files.h"
#include "common/units.h"
#include "system/dynamics_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace servodrift::system
{
  namespace
  {
    std::string c(double v)
    {
      return format_cell(v);
    }

    /// "plot 'modes.dat' index 0 using 1:<column> ... title '<name>', ..." (names may hold spaces)
    std::string mode_plot(const std::vector<std::string> &names, int column)
    {
      std::string command = "plot ";
      for (std::size_t k = 0; k < names.size(); ++k)
        command += (k ? ", " : "") + std::string("'modes.dat' index ") + std::to_string(k) + " using 1:" +
                   std::to_string(column) + " with linespoints title '" + names[k] + "'";
      return command + "\n";
    }

    /// The continuous phase [deg] of a response H at f: the phase at the grid point nearest f plus
    /// the argument of H(f) over H there
    double linear_phase(const FrequencyResponse &r, double f, std::complex<double> h)
    {
      std::size_t k = 0;
      for (std::size_t j = 1; j < r.frequencies.size(); ++j)
        if (std::abs(std::log(r.frequencies[j] / f)) < std::abs(std::log(r.frequencies[k] / f)))
          k = j;
      return r.phase_degrees[k] + degrees(h / r.values[k]);
    }

    /// the studied drift temperature nearest the reference temperature (the first if none was)
    std::size_t nearest_studied(const DynamicsResults &r, double T0)
    {
      std::size_t best = 0;
      const auto distance = [&](std::size_t k) {
        return r.temperatures[k].sine_study.empty() ? 1e300 : std::abs(r.temperatures[k].temperature - T0);
      };
      for (std::size_t k = 1; k < r.temperatures.size(); ++k)
        if (distance(k) < distance(best))
          best = k;
      return best;
    }
  } // namespace

  void write_dynamics_plots(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir,
                            PlotFiles &files)
  {
    if (!valve.output.plots || r.temperatures.empty())
      return;
    prepare_output_directory(dir);
    // one curve per temperature, coloured by it (a colour bar), in the Bode and step plots

    // Bode plot of the brake pressure, blocks by temperature
    std::ostringstream bode;
    bode << "# blocks by temperature; frequency[Hz] brake_pressure_amplitude[dB] brake_pressure_phase[deg] "
            "spool_displacement_amplitude[dB] spool_displacement_phase[deg] temperature[degC]\n";
    for (std::size_t k = 0; k < r.temperatures.size(); ++k)
      {
        const auto &d = r.temperatures[k];
        bode << "# " << d.temperature << " degC\n";
        for (std::size_t j = 0; j < d.brake_pressure.frequencies.size(); ++j)
          bode << c(d.brake_pressure.frequencies[j]) << ' ' << c(d.brake_pressure.amplitude_db[j]) << ' '
               << c(d.brake_pressure.phase_degrees[j]) << ' ' << c(d.spool_displacement.amplitude_db[j]) << ' '
               << c(d.spool_displacement.phase_degrees[j]) << ' ' << c(d.temperature) << '\n';
        bode << "\n\n";
      }
    write_file_atomically(dir + "/bode.dat", bode.str());

    // large step responses, blocks by temperature
    std::ostringstream step;
    step << "# blocks by temperature; time[ms] brake_pressure[MPa] spool_displacement[um] flapper_displacement[um] "
            "temperature[degC]\n";
    double shown = 0; // time axis: past the slowest 2 % settling of p_B
    for (std::size_t k = 0; k < r.temperatures.size(); ++k)
      {
        const auto &d = r.temperatures[k];
        const auto &s = d.large_step;
        shown = std::max(shown, 1.3 * s.metrics[0].settling_time.value_or(s.duration));
        step << "# " << d.temperature << " degC\n";
        for (std::size_t j = 0; j < s.times.size(); ++j)
          step << c(1e3 * s.times[j]) << ' ' << c(1e-6 * s.states[j].brake_pressure) << ' '
               << c(1e6 * s.states[j].spool_displacement) << ' '
               << c(1e6 * (valve.armature.pivot_to_nozzle_distance * s.states[j].angle - d.hydraulic_null)) << ' '
               << c(d.temperature) << '\n';
        step << "\n\n";
      }
    write_file_atomically(dir + "/step.dat", step.str());

    // modes vs temperature, blocks by mode name
    std::map<std::string, std::ostringstream> by_name;
    std::vector<std::string> names;
    for (const auto &d : r.temperatures)
      for (const auto &m : d.modes)
        {
          if (!by_name.count(m.name))
            names.push_back(m.name);
          by_name[m.name] << c(d.temperature) << ' ' << c(m.natural_frequency) << ' ' << c(m.damping_ratio) << '\n';
        }
    std::ostringstream modes;
    modes << "# blocks by mode; temperature[degC] natural_frequency[Hz] damping_ratio[1]\n";
    for (const auto &name : names)
      modes << "# " << name << "\n" << by_name[name].str() << "\n\n";
    write_file_atomically(dir + "/modes.dat", modes.str());

    // the sine study at the studied temperature nearest T0 (if stable there): blocks by amplitude, the linear
    // response last
    const auto &d0 = r.temperatures[nearest_studied(r, valve.operating.reference_temperature)];
    const bool sine_plot = !d0.sine_study.empty();
    std::ostringstream sine;
    sine << "# " << d0.temperature << " degC; blocks by amplitude, then linear; frequency[Hz] "
         << "brake_pressure_amplitude[dB re DC] brake_pressure_phase[deg]\n";
    std::string sine_titles;
    for (const auto *study : {&d0.sine_study, &d0.sine_study_down}) // blocks: up sweeps, then down
      for (std::size_t a = 0; a < valve.dynamics.sine_amplitudes.size(); ++a)
        {
          sine << "# amplitude " << valve.dynamics.sine_amplitudes[a] << " of rated, swept "
               << (study == &d0.sine_study ? "up" : "down") << "\n";
          for (std::size_t j = 0; j < study->size(); ++j)
            {
              // the phase continuous like the linear one's: the linear phase there plus the difference
              const auto &check = d0.sine_checks[j];
              const auto &s = (*study)[j][a];
              const double linear = linear_phase(d0.brake_pressure, check.frequency, check.linear[0]);
              sine << c(check.frequency) << ' ' << c(decibel(s.gain[0] / check.dc_gain[0])) << ' '
                   << c(linear + degrees(s.gain[0] / check.linear[0])) << '\n';
            }
          sine << "\n\n";
          if (study == &d0.sine_study)
            sine_titles += (sine_titles.empty() ? "'" : " '") + c(100 * valve.dynamics.sine_amplitudes[a]) + " %'";
        }
    sine << "# linear\n";
    for (std::size_t j = 0; j < d0.brake_pressure.frequencies.size(); ++j)
      sine << c(d0.brake_pressure.frequencies[j]) << ' ' << c(d0.brake_pressure.amplitude_db[j]) << ' '
           << c(d0.brake_pressure.phase_degrees[j]) << '\n';
    if (sine_plot)
      write_file_atomically(dir + "/sine.dat", sine.str());

    const std::size_t n_amplitudes = valve.dynamics.sine_amplitudes.size();
    const std::string n = std::to_string(r.temperatures.size() - 1);
    const std::string palette = "set palette defined (0 'blue', 1 'green', 2 'orange', 3 'red')\nset cbrange [" +
                                c(r.temperatures.front().temperature) + ":" + c(r.temperatures.back().temperature) +
                                "]\nset cblabel 'temperature [degC]'\n";
    const std::vector<Plot> plots = {
      {"bode_brake_pressure",
       palette + "set multiplot layout 2,1 title 'Brake pressure / command current, linearised at the bias'\n"
                 "set logscale x\nset grid\nset ylabel 'amplitude [dB re DC]'\n"
                 "plot for [k=0:" + n + "] 'bode.dat' index k using 1:2:6 with lines lw 1.5 lc palette notitle\n"
                 "set xlabel 'frequency [Hz]'\nset ylabel 'phase [deg]'\n"
                 "plot for [k=0:" + n + "] 'bode.dat' index k using 1:3:6 with lines lw 1.5 lc palette notitle\n"
                 "unset multiplot\n"},
      {"step_response",
       palette + "set multiplot layout 3,1 title 'Step 0 -> rated current'\nset grid\n"
                 "set xrange [0:" + c(1e3 * shown) + "]\nset ylabel 'p_B [MPa]'\n"
                 "plot for [k=0:" + n + "] 'step.dat' index k using 1:2:5 with lines lc palette notitle\n"
                 "set ylabel 'x_v [um]'\n"
                 "plot for [k=0:" + n + "] 'step.dat' index k using 1:3:5 with lines lc palette notitle\n"
                 "set xlabel 'time [ms]'\nset ylabel 'x_f [um]'\n"
                 "plot for [k=0:" + n + "] 'step.dat' index k using 1:4:5 with lines lc palette notitle\n"
                 "unset multiplot\n"},
      {"modes", "set multiplot layout 2,1 title 'Modes at the bias'\nset grid\nset key outside right\nset logscale y\n"
                "set ylabel 'natural frequency [Hz]'\n" + mode_plot(names, 2) +
                  "unset logscale y\nset xlabel 'temperature [degC]'\nset ylabel 'damping ratio [1]'\n" +
                  mode_plot(names, 3) + "unset multiplot\n"},
    };
    std::vector<Plot> all = plots;
    // the small-signal check at the temperature nearest T0 that has one: the linear response, the
    // nonlinear first harmonic of each point, labelled with the amplitude it was taken at
    std::size_t checked = r.temperatures.size();
    for (std::size_t k = 0; k < r.temperatures.size(); ++k)
      if (!r.temperatures[k].sine_checks.empty() &&
          (checked == r.temperatures.size() ||
           std::abs(r.temperatures[k].temperature - valve.operating.reference_temperature) <
             std::abs(r.temperatures[checked].temperature - valve.operating.reference_temperature)))
        checked = k;
    if (checked < r.temperatures.size())
      {
        const auto &dc = r.temperatures[checked];
        std::ostringstream points, labels;
        points << "# " << dc.temperature << " degC: frequency[Hz] brake_pressure_amplitude[dB re DC] "
               << "brake_pressure_phase[deg] amplitude_taken[% of rated]; then the linear response\n";
        for (const auto &check : dc.sine_checks)
          {
            const auto &s = check.taken();
            const double amplitude = decibel(s.gain[0] / check.dc_gain[0]);
            points << c(check.frequency) << ' ' << c(amplitude) << ' '
                   << c(linear_phase(dc.brake_pressure, check.frequency, check.linear[0]) + degrees(s.gain[0] / check.linear[0]))
                   << ' ' << c(100 * s.amplitude / valve.operating.rated_current) << '\n';
            char percent[16];
            std::snprintf(percent, sizeof(percent), "%.3g", 100 * s.amplitude / valve.operating.rated_current);
            labels << "set label '" << percent << " %" << (check.linear_limit ? "" : "*")
                   << "' at " << c(check.frequency) << "," << c(amplitude) << " offset 0.5,0.8 font ',8'\n";
          }
        points << "\n\n# linear\n";
        for (std::size_t j = 0; j < dc.brake_pressure.frequencies.size(); ++j)
          points << c(dc.brake_pressure.frequencies[j]) << ' ' << c(dc.brake_pressure.amplitude_db[j]) << ' '
                 << c(dc.brake_pressure.phase_degrees[j]) << '\n';
        write_file_atomically(dir + "/sine_check.dat", points.str());
        all.push_back({"sine_check",
                       "set multiplot layout 2,1 title 'Small-signal check at " + c(dc.temperature) +
                         " degC: nonlinear first harmonic at the amplitude taken [% of rated] against the linearisation'\n"
                         "set logscale x\nset grid\nset key top right\nset ylabel 'p_B amplitude [dB re DC]'\n" +
                         labels.str() +
                         "plot 'sine_check.dat' index 1 using 1:2 with lines lc 'black' title 'linear', '' index 0 "
                         "using 1:2 with points pt 7 lc 'blue' title 'nonlinear'\nunset label\n"
                         "set xlabel 'frequency [Hz]'\nset ylabel 'phase [deg]'\n"
                         "plot 'sine_check.dat' index 1 using 1:3 with lines lc 'black' title 'linear', '' index 0 "
                         "using 1:3 with points pt 7 lc 'blue' title 'nonlinear'\nunset multiplot\n"});
      }
    if (sine_plot)
      all.push_back(
      {"sine_amplitude_study",
       "titles = \"" + sine_titles + "\"\nset multiplot layout 2,1 title 'Brake pressure, nonlinear first harmonic at " +
         c(d0.temperature) + " degC'\nset logscale x\nset grid\nset key outside right\nset ylabel 'amplitude [dB re DC]'\n"
         "plot 'sine.dat' index " + std::to_string(2 * n_amplitudes) +
         " using 1:2 with lines lc 'black' title 'linear', for [k=0:" + std::to_string(n_amplitudes - 1) +
         "] 'sine.dat' index k using 1:2 with linespoints lc k+1 title word(titles,k+1).' up', for [k=0:" +
         std::to_string(n_amplitudes - 1) + "] 'sine.dat' index k+" + std::to_string(n_amplitudes) +
         " using 1:2 with linespoints dt 2 lc k+1 title word(titles,k+1).' down'\n"
         "set xlabel 'frequency [Hz]'\nset ylabel 'phase [deg]'\n"
         "plot 'sine.dat' index " + std::to_string(2 * n_amplitudes) +
         " using 1:3 with lines lc 'black' title 'linear', for [k=0:" + std::to_string(n_amplitudes - 1) +
         "] 'sine.dat' index k using 1:3 with linespoints lc k+1 title word(titles,k+1).' up', for [k=0:" +
         std::to_string(n_amplitudes - 1) + "] 'sine.dat' index k+" + std::to_string(n_amplitudes) +
         " using 1:3 with linespoints dt 2 lc k+1 title word(titles,k+1).' down'\nunset multiplot\n"});
    render_plots(valve, all, dir, files);
  }
} // namespace servodrift::system
