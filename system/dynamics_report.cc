#include "system/dynamics_report.h"

#include "common/units.h"
#include "system/dynamics_output.h"
#include "system/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace servodrift::system
{
  namespace
  {
    std::string fmt(double v, int digits = 4)
    {
      return report_number(v, digits);
    }
    std::string fmt(const std::optional<double> &v, double scale = 1, int digits = 4)
    {
      return v ? fmt(*v * scale, digits) : "-";
    }

    const Mode &armature_mode(const TemperatureDynamics &d)
    {
      return *std::max_element(d.modes.begin(), d.modes.end(),
                               [](const Mode &a, const Mode &b) { return a.participation[0] < b.participation[0]; });
    }

    void summary_table(std::ostream &out, const DynamicsResults &r)
    {
      out << "| T [degC] | p_B at bias [MPa] | bandwidth -3 dB [Hz] | -90 deg [Hz] | armature f_n [Hz] | armature zeta | "
             "step 0 -> rated: p_B rise [ms] | overshoot [%] | settling 2 % [ms] | small step: overshoot [%] | settling [ms] |\n"
          << "|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const auto &d : r.temperatures)
        {
          const Mode &a = armature_mode(d);
          const auto &L = d.large_step.metrics[0], &S = d.small_step.metrics[0];
          out << "| " << fmt(d.temperature) << " | " << fmt(1e-6 * d.bias_point.brake_pressure) << " | "
              << fmt(d.brake_pressure.bandwidth) << " | " << fmt(d.brake_pressure.phase_90_frequency) << " | "
              << fmt(a.natural_frequency) << " | " << fmt(a.damping_ratio, 3) << " | " << fmt(L.rise_time, 1e3) << " | "
              << fmt(L.overshoot, 3) << " | " << fmt(L.settling_time, 1e3) << " | " << fmt(S.overshoot, 3) << " | "
              << fmt(S.settling_time, 1e3) << " |\n";
        }
      out << "\n";
    }

    /// The cold-soak starts: how long the brake pressure takes to regulate, and its worst excursion
    void cold_starts(std::ostream &out, const ValveDescription &valve, const DynamicsResults &r)
    {
      const auto &p = valve.dynamics;
      if (p.cold_start_temperatures.empty())
        return;
      out << "### Cold-soak start\n\nThe valve soaked at each temperature and at rest (every pressure at return, "
             "armature and spool centred); at t = 0 the supply and "
          << fmt(1e3 * p.cold_start_current * valve.operating.rated_current) << " mA ("
          << fmt(100 * p.cold_start_current)
          << " % of rated) are applied. Time to regulate: from then until p_B stays within 2 % of the change to its "
             "static value; overshoot: p_B's largest excursion beyond that value, in % of the change (`system/"
             "step_metrics.csv` and `step_response.csv`, step `cold-start`).\n\n"
          << "| T [degC] | p_B final [MPa] | time to regulate [s] | rise 10-90 % [ms] | overshoot [%] | simulated [s] | "
             "flapper on a nozzle | spool on a stop |\n|---|---|---|---|---|---|---|---|\n";
      for (const ColdStart &c : r.cold_starts)
        {
          const StepMetrics &m = c.response.metrics[0];
          out << "| " << fmt(c.temperature) << " | " << fmt(1e-6 * m.final) << " | "
              << (m.settling_time ? fmt(*m.settling_time, 3) : "not within " + fmt(c.response.duration, 3))
              << " | " << fmt(m.rise_time, 1e3) << " | " << fmt(m.overshoot, 3) << " | " << fmt(c.response.duration, 3)
              << " | " << (c.response.flapper_contact ? "yes" : "no") << " | " << (c.response.spool_on_stop ? "yes" : "no")
              << " |\n";
        }
      std::string skipped;
      for (double T : p.cold_start_temperatures)
        if (std::none_of(r.cold_starts.begin(), r.cold_starts.end(), [T](const ColdStart &c) { return c.temperature == T; }))
          skipped += (skipped.empty() ? "" : ", ") + fmt(T);
      if (!skipped.empty())
        out << "\nNot computed, beyond the table temperatures (`Sweeps/Table temperatures`): " << skipped << " degC.\n";
      out << "\n";
    }

    void checks(std::ostream &out, const ValveDescription &valve, const DynamicsResults &r)
    {
      const double rated = valve.operating.rated_current;
      // an unstable bias point has no steady state to settle on and no linear frequency response to
      // compare with: those checks are made at the stable temperatures
      double armature = 0, tau = 0, drift = 0, rest = 0, worst_db = 0, worst_deg = 0, halving_db = 0, halving_deg = 0;
      double smallest = 1e300, largest = 0;
      std::string skipped, not_linear;
      for (const auto &d : r.temperatures)
        {
          armature = std::max(armature, std::abs(d.checks.armature_blocked / d.checks.armature_closed_form - 1));
          tau = std::max(tau, std::abs(d.checks.pressure_time_constant / d.checks.pressure_time_constant_tables - 1));
          drift = std::max(drift, d.steady.drift_from_static);
          if (!d.stable())
            {
              skipped += (skipped.empty() ? "" : ", ") + fmt(d.temperature);
              continue;
            }
          rest = std::max(rest, d.steady.distance_from_rest);
          for (const auto &c : d.sine_checks)
            {
              const auto h = c.taken().gain[0] / c.linear[0], g = c.last_halving();
              worst_db = std::max(worst_db, std::abs(decibel(h)));
              worst_deg = std::max(worst_deg, std::abs(degrees(h)));
              halving_db = std::max(halving_db, std::abs(decibel(g)));
              halving_deg = std::max(halving_deg, std::abs(degrees(g)));
              smallest = std::min(smallest, c.taken().amplitude);
              largest = std::max(largest, c.taken().amplitude);
              if (!c.linear_limit)
                not_linear += (not_linear.empty() ? "" : ", ") + fmt(c.frequency) + " Hz at " + fmt(d.temperature) + " degC";
            }
        }
      const auto verdict = [](bool pass) { return pass ? " (pass)" : " (**fail**)"; };
      const auto &first = r.temperatures.front().checks, &last = r.temperatures.back().checks;
      out << "Checks (`system/dynamics_summary.csv`"
          << (skipped.empty() ? "" : "; the start-up and the sine responses only where the bias point is stable, not at " +
                                       skipped + " degC")
          << "):\n\n"
          << "- static = dynamic at zero rates: integrated from the static operating point the valve stays within "
          << fmt(drift, 2) << " of each state's scale (required < 1e-8)" << verdict(drift < 1e-8)
          << "; started from rest it settles within " << fmt(rest, 2) << " of it (required < 1e-6)" << verdict(rest < 1e-6)
          << ".\n"
          << "- armature mode with the spool blocked and the control pressures following the flapper (model.md 2.5, "
             "C13): "
          << fmt(first.armature_blocked) << " Hz against sqrt((K_a - K_m + r^2 K_f)/J_a)/(2 pi) = "
          << fmt(first.armature_closed_form) << " Hz at " << fmt(r.temperatures.front().temperature)
          << " degC (largest difference " << fmt(100 * armature, 2)
          << " %). With compressible cavities it falls to " << fmt(first.armature_compressible)
          << " Hz, in the coupled valve to " << fmt(first.armature_coupled) << " Hz (" << fmt(last.armature_coupled)
          << " Hz at " << fmt(r.temperatures.back().temperature) << " degC): doc/method.md explains why.\n"
          << "- control-cavity pressure time constant at null: " << fmt(1e3 * first.pressure_time_constant) << " ms from "
             "the linearisation, V/(beta_e dQ/dp) = " << fmt(1e3 * first.pressure_time_constant_tables)
          << " ms with the tables' slopes (largest difference " << fmt(100 * tau, 2) << " %), "
          << fmt(1e3 * first.pressure_time_constant_closed_form) << " ms for turbulent orifices (Q ~ sqrt(dp)).\n"
          << "- small-signal sine against the linearisation, at the linear limit: largest difference " << fmt(worst_db, 2)
          << " dB and " << fmt(worst_deg, 2) << " deg (required " << fmt(SineCheckLimits::decibel) << " dB, "
          << fmt(SineCheckLimits::degree) << " deg)"
          << verdict(worst_db < SineCheckLimits::decibel && worst_deg < SineCheckLimits::degree && not_linear.empty())
          << ". Each point starts at the largest amplitude whose linear excursion of spool and flapper stays within "
             "`Dynamics/Linearity margin` of the distance to their nearest edge, and halves it until halving moves "
             "the response by at most "
          << fmt(SineCheckLimits::halving_fraction * SineCheckLimits::decibel) << " dB and "
          << fmt(SineCheckLimits::halving_fraction * SineCheckLimits::degree) << " deg (the last halving moved it by "
          << fmt(halving_db, 2) << " dB and " << fmt(halving_deg, 2) << " deg at most); the points were taken at "
          << fmt(100 * smallest / rated, 3) << " to " << fmt(100 * largest / rated, 3)
          << " % of rated (each point's amplitude: `system/sine_response.csv`, kind `check`; plot `sine_check`)"
          << (not_linear.empty() ? std::string(".") :
                                   ". **Not at the linear limit** after " + std::to_string(SineCheckLimits::halvings) +
                                     " halvings: " + not_linear + ".")
          << "\n\n";
    }

    /// The amplitude at which each small-signal point was taken, and the halvings it took.
    void amplitudes_taken(std::ostream &out, const ValveDescription &valve, const DynamicsResults &r)
    {
      const auto &f = valve.dynamics.sine_frequencies;
      out << "Amplitude of each small-signal point [% of rated] (halvings from the first amplitude; * not at the "
             "linear limit):\n\n| T [degC] |";
      for (double x : f)
        out << " " << fmt(x) << " Hz |";
      out << "\n|---:|";
      for (std::size_t j = 0; j < f.size(); ++j)
        out << "---:|";
      out << "\n";
      for (const auto &d : r.temperatures)
        {
          if (d.sine_checks.empty())
            continue;
          out << "| " << fmt(d.temperature) << " |";
          for (const auto &c : d.sine_checks)
            out << " " << fmt(100 * c.taken().amplitude / valve.operating.rated_current, 3) << " ("
                << c.halvings.size() - 1 << ")" << (c.linear_limit ? "" : " *") << " |";
          out << "\n";
        }
      out << "\n";
    }

    /// The sine responses (checks and study) whose time integration stopped: how many, and why the
    /// first did
    void failed_integrations(std::ostream &out, const DynamicsResults &r)
    {
      std::size_t failed = 0;
      std::string first;
      const auto count = [&](const SineResponse &s) {
        if (s.failure.empty())
          return;
        if (failed++ == 0)
          first = s.failure;
      };
      for (const auto &d : r.temperatures)
        {
          for (const SineCheck &c : d.sine_checks)
            for (const SineResponse &s : c.halvings)
              count(s);
          for (const auto *study : {&d.sine_study, &d.sine_study_down})
            for (const auto &at_frequency : *study)
              for (const SineResponse &s : at_frequency)
                count(s);
        }
      if (failed > 0)
        out << failed << " sine responses stopped because their time integration failed; they count as not periodic "
            << "(`integration_failed` in `system/sine_response.csv`). The first: " << first << ".\n\n";
    }

    void study(std::ostream &out, const ValveDescription &valve, const DynamicsResults &r)
    {
      const auto &p = valve.dynamics;
      out << "Large signals (`Dynamics/Sine amplitudes`, `system/sine_response.csv`): the first harmonic of p_B "
             "against the linearisation, over the stable ones of the study's temperatures (`Dynamics/Large-signal "
             "temperatures`) and all sine frequencies, the frequencies swept up and down (each starting from its "
             "neighbour's periodic state):\n\n"
          << "| amplitude [% of rated] | largest departure of a periodic response [dB] | at [Hz] | periodic | sub-harmonic responses | "
             "up and down sweeps differ (jump) | metering edge opened | flapper on a nozzle | spool on a stop |\n"
             "|---|---|---|---|---|---|---|---|---|\n";
      std::string jumps;
      for (std::size_t a = 0; a < p.sine_amplitudes.size(); ++a)
        {
          double worst = 0, at = 0;
          std::size_t periodic = 0, sub = 0, differ = 0, lap = 0, contact = 0, stop = 0, n = 0;
          for (const auto &d : r.temperatures)
            for (std::size_t j = 0; j < d.sine_study.size(); ++j) // none where not studied
              {
                for (const SineResponse *s : {&d.sine_study[j][a], &d.sine_study_down[j][a]})
                  {
                    const double departure = decibel(s->gain[0] / d.sine_checks[j].linear[0]);
                    if (s->periodic && std::abs(departure) > std::abs(worst))
                      worst = departure, at = s->frequency;
                    ++n;
                    periodic += s->periodic;
                    sub += s->periodic && s->response_periods > 1;
                    lap += s->beyond_lap;
                    contact += s->flapper_contact;
                    stop += s->spool_on_stop;
                  }
                if (sweeps_differ(d.sine_study[j][a], d.sine_study_down[j][a]))
                  {
                    ++differ;
                    jumps += (jumps.empty() ? "" : ", ") + fmt(100 * p.sine_amplitudes[a]) + " % at " +
                             fmt(d.sine_checks[j].frequency) + " Hz, " + fmt(d.temperature) + " degC";
                  }
              }
          const auto of = [&](std::size_t k, std::size_t total) { return std::to_string(k) + " of " + std::to_string(total); };
          out << "| " << fmt(100 * p.sine_amplitudes[a]) << " | " << fmt(worst, 3) << " | " << fmt(at) << " | "
              << of(periodic, n) << " | " << of(sub, n) << " | " << of(differ, n / 2) << " | " << of(lap, n) << " | "
              << of(contact, n) << " | " << of(stop, n) << " |\n";
        }
      out << "\nA sub-harmonic response repeats only after m > 1 input periods (`response_periods`); a metering "
             "edge opened means the spool left its lap, where the brake port's flow gain is that of the orifice, "
             "not of the lap leakage. Up and down sweeps differ where both are periodic and their first harmonics "
             "differ by more than 1 dB or 10 deg: two responses at one frequency, between which a sweep jumps"
          << (jumps.empty() ? " (none here).\n\n" : ": " + jumps + ".\n\n");
      failed_integrations(out, r);
    }

    void fixed_time(std::ostream &out, const FixedTimeStudy &s)
    {
      out << "theta_d = " << fmt(s.deviation_angle / units::degree)
          << " deg:\n\n| reading time [s] | spool displacement ratio | brake pressure ratio |\n|---|---|---|\n";
      for (std::size_t j = 0; j < s.reading_times.size(); ++j)
        out << "| " << fmt(s.reading_times[j]) << (s.best && *s.best == j ? " (nearest the paper)" : "") << " | "
            << fmt(s.displacement_slope_ratio[j], 1, 3) << " | " << fmt(s.pressure_slope_ratio[j], 1, 3) << " |\n";
      out << "| steady state | " << fmt(s.static_displacement_slope_ratio, 1, 3) << " | "
          << fmt(s.static_pressure_slope_ratio, 1, 3) << " |\n\n";
      if (!s.best)
        out << "No reading time gives both ratios positive: no fixed-time reading at this angle reproduces the "
               "paper's shapes.\n\n";
      else
        {
          const double rx = *s.displacement_slope_ratio[*s.best], rp = *s.pressure_slope_ratio[*s.best];
          const bool close = std::abs(std::log(rx / paper_displacement_slope_ratio)) < std::log(1.25) &&
                             std::abs(std::log(rp / paper_pressure_slope_ratio)) < std::log(1.25);
          out << "Nearest the paper: t = " << fmt(s.reading_times[*s.best]) << " s with " << fmt(rx, 3) << " and "
              << fmt(rp, 3) << (close ? ": both within 25 % of the paper's.\n\n" : ": not within 25 % of the paper's for both.\n\n");
        }
    }
  } // namespace

  void dynamics_section(std::ostream &out, const ValveDescription &valve, const DynamicsResults &r)
  {
    out << "## Dynamics\n\n";
    if (r.temperatures.empty())
      return;
    const auto &p = valve.dynamics;
    out << "The valve's equations (E29-E37) integrated with CVODE (BDF) and linearised at the bias, "
        << fmt(1e3 * p.bias * valve.operating.rated_current) << " mA (" << fmt(100 * p.bias)
        << " % of rated); " << (valve.torque_motor.voltage_drive ? "voltage" : "current") << " drive, brake port "
        << (valve.spool.brake_port == SpoolParameters::BrakePort::blocked_port ? "blocked at the valve" :
                                                                                "into the brake volume V_B")
        << " with no load flow. Bandwidth and -90 degree frequency of the brake pressure per command current; "
           "the armature mode is the one with the largest armature participation (`system/modes.csv`).\n\n";
    summary_table(out, r);
    for (const auto &d : r.temperatures)
      for (const auto &m : d.modes)
        if (m.eigenvalue.real() > 0)
          out << "**Unstable at " << fmt(d.temperature) << " degC:** the " << m.name << " mode (" << fmt(m.natural_frequency)
              << " Hz) grows at " << fmt(m.eigenvalue.real()) << " 1/s: the valve oscillates about the bias instead of "
                 "settling on it, so its bandwidth and step figures there describe that oscillation.\n\n";
    cold_starts(out, valve, r);
    checks(out, valve, r);
    amplitudes_taken(out, valve, r);
    study(out, valve, r);
    if (!r.fixed_time.empty())
      {
        out << "### Fixed-time readings of the start-up (model.md C9)\n\n"
            << "The start-up of the valve from rest (supply switched on, every pressure at return, armature and "
               "spool centred), each deviation angle against theta_d = 0, with the drift measures (E40) read at "
               "fixed times. Slope ratio = (d(50) - d(40))/(d(120) - d(110)); paper: "
            << paper_displacement_slope_ratio << " (spool displacement, i = 0) and " << paper_pressure_slope_ratio
            << " (brake pressure, rated current). All readings: `system/fixed_time_study.csv`; doc/validation.md "
               "discusses the result.\n\n";
        for (const auto &s : r.fixed_time)
          fixed_time(out, s);
      }
  }
} // namespace servodrift::system
