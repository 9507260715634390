#include "system/report.h"

#include "common/output_files.h"
#include "common/units.h"
#include "common/version.h"
#include "system/dynamics_report.h"
#include "system/calibration_output.h"
#include "system/tolerance_output.h"
#include "system/system_stage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <sstream>

namespace servodrift::system
{
  std::string report_number(double v, int digits)
  {
    if (!std::isfinite(v))
      return "n/a";
    char b[48];
    std::snprintf(b, sizeof(b), "%.*g", digits, v);
    return b;
  }

  namespace
  {
    std::string fmt(double v, int digits = 4)
    {
      return report_number(v, digits);
    }

    /// A null-shift current as the report shows it [A]: below 1 nA, the round-off of a valve nulled
    /// at that temperature, it is 0.
    double shown_current(double current)
    {
      return std::abs(current) > 1e-9 ? current : 0.0;
    }

    std::string percent(double value, double reference)
    {
      char b[32];
      std::snprintf(b, sizeof(b), "%+.2f %%", 100 * (value / reference - 1));
      return b;
    }

    const StageCoefficients *at_temperature(const SystemResults &r, double T)
    {
      for (const auto &c : r.coefficients)
        if (c.temperature == T)
          return &c;
      return nullptr;
    }

    std::optional<std::size_t> temperature_index(const DriftMap &m, double T)
    {
      for (std::size_t t = 0; t < m.temperatures.size(); ++t)
        if (m.temperatures[t] == T)
          return t;
      return std::nullopt;
    }

    struct Reference
    {
      const char *quantity, *unit;
      double scale; // report unit per SI unit
      double rv1_40, rv1_120; // model.md (NaN: not given)
      const char *source;
      double (*get)(const StageCoefficients &);
    };

    void stage_table(std::ostream &out, const SystemResults &r)
    {
      const double nan = std::nan("");
      const Reference refs[] = {
        {"T(theta = 0.1 deg, i = 0)", "N*m", 1, 0.019772, 0.018926, "C2 (paper FEM: 0.019835 / 0.018974)",
         [](const StageCoefficients &c) { return c.motor.torque_at_tenth_degree; }},
        {"K_m, secant at 0.1 deg", "N*m/rad", 1, 11.33, 10.84, "C1, C2 (2.2: 11.36 / 10.87; paper 11.365 / 10.871)",
         [](const StageCoefficients &c) { return c.motor.secant_magnetic_spring; }},
        {"K_m, slope at 0", "N*m/rad", 1, 11.23, 10.75, "C1",
         [](const StageCoefficients &c) { return c.motor.magnetic_spring; }},
        {"K_t", "N*m/A", 1, 0.954, 0.934, "C2, 2.2", [](const StageCoefficients &c) { return c.motor.torque_constant; }},
        {"K_a", "N*m/rad", 1, 21.44, 20.93, "2.4, C3 (E11; 3D FEM: 21.57 at 40 degC)", [](const StageCoefficients &c) { return c.spring_stiffness; }},
        {"C_d0 at null", "1", 1, 0.778, 0.799, "E21, 2.6", [](const StageCoefficients &c) { return c.orifice_discharge; }},
        {"C_dn at null", "1", 1, 0.610, 0.631, "E22, 2.6", [](const StageCoefficients &c) { return c.nozzle_discharge; }},
        {"flapper force difference at x_f = 10 um", "N", 1, 0.595, nan, "1.10 (paper CFD: 0.575 at 40 degC)",
         [](const StageCoefficients &c) { return c.force_difference_10um; }},
        {"K_f at null", "kN/m", 1e-3, 59.5, 57.2, "2.6 (paper table: 57.5 / 34.5)",
         [](const StageCoefficients &c) { return c.flow_force_stiffness; }},
        {"null control pressure", "MPa", 1e-6, 10.8, nan, "2.6", [](const StageCoefficients &c) { return c.null_control_pressure; }},
        {"quiescent pilot flow", "L/min", 6e4, 0.58, nan, "2.6", [](const StageCoefficients &c) { return c.quiescent_flow; }},
        {"K_a - K_m + r^2 K_f", "N*m/rad", 1, 16.0, nan, "1.12", [](const StageCoefficients &c) { return c.net_stiffness; }},
      };
      const StageCoefficients *c40 = at_temperature(r, 40), *c120 = at_temperature(r, 120);
      if (!c40 || !c120)
        {
          out << "The drift temperatures do not include 40 and 120 degC, where model.md gives its values; see "
                 "system/stage_coefficients.csv.\n\n";
          return;
        }
      out << "| quantity | unit | 40 degC | model.md | diff | 120 degC | model.md | diff | source |\n"
          << "|---|---|---|---|---|---|---|---|---|\n";
      for (const auto &q : refs)
        {
          const double v40 = q.get(*c40) * q.scale, v120 = q.get(*c120) * q.scale;
          out << "| " << q.quantity << " | " << q.unit << " | " << fmt(v40, 5) << " | " << fmt(q.rv1_40, 5) << " | "
              << (std::isfinite(q.rv1_40) ? percent(v40, q.rv1_40) : "") << " | " << fmt(v120, 5) << " | "
              << fmt(q.rv1_120, 5) << " | " << (std::isfinite(q.rv1_120) ? percent(v120, q.rv1_120) : "") << " | "
              << q.source << " |\n";
        }
      out << "\nTemperature trend 40 -> 120 degC: T(0.1 deg) " << percent(c120->motor.torque_at_tenth_degree, c40->motor.torque_at_tenth_degree)
          << " (paper Fig. 7: -4.34 %), K_a " << percent(c120->spring_stiffness, c40->spring_stiffness)
          << " (1.6: -2.4 %), C_dn " << percent(c120->nozzle_discharge, c40->nozzle_discharge)
          << " (paper: about 2 % at most), K_f " << percent(c120->flow_force_stiffness, c40->flow_force_stiffness)
          << " (physics E23: -4 %; paper CFD: -40 %).\n\n";
    }

    void operating_points(std::ostream &out, const DriftMap &m)
    {
      out << "| T [degC] | i [mA] | theta [deg] | x_f [um] | p_L [MPa] | p_R [MPa] | x_v [um] | p_B [MPa] | flapper | spool |\n"
          << "|---|---|---|---|---|---|---|---|---|---|\n";
      std::size_t zero = 0;
      for (std::size_t a = 0; a < m.deviation_angles.size(); ++a)
        if (m.deviation_angles[a] == 0.0)
          zero = a;
      for (std::size_t t : {std::size_t(0), m.temperatures.size() - 1})
        for (const OperatingPoint *o : {&m.at(t, zero).zero_current, &m.at(t, zero).rated_current})
          out << "| " << fmt(o->temperature) << " | " << fmt(o->current * 1e3) << " | " << fmt(o->angle / units::degree)
              << " | " << fmt(o->flapper_displacement * 1e6) << " | " << fmt(o->bridge.left_pressure * 1e-6) << " | "
              << fmt(o->bridge.right_pressure * 1e-6) << " | " << fmt(o->spool.displacement * 1e6) << " | "
              << fmt(o->spool.brake_pressure * 1e-6) << " | " << to_string(o->flapper) << " | "
              << to_string(o->spool.state) << " |\n";
      out << "\n(deviation angle " << fmt(m.deviation_angles[zero] / units::degree)
          << " deg; blocked brake port; p_B is gauge.)\n\n";
    }

    void drift_section(std::ostream &out, const ValveDescription &valve, const DriftMap &m)
    {
      const auto &o = valve.offsets;
      const char *target = o.deviation_target == OffsetParameters::Target::magnetic_null ? "the magnetic null theta_m" :
                           o.deviation_target == OffsetParameters::Target::spring_tube_rest_angle ?
                                                                                         "the spring-tube rest angle theta_s (E38)" :
                                                                                         "the hydraulic null x_n";
      out << "Convention: **" << (m.nulled_at_reference ? "nulled at reference" : "as assembled") << "** (D8); the "
          << "deviation angle theta_d drives " << target << ". Deviations are taken relative to "
          << (m.nulled_at_reference ? "the same valve at the reference temperature" : "theta_d = 0 at the same temperature")
          << " (D9). theta_d from " << fmt(m.deviation_angles.front() / units::degree) << " to "
          << fmt(m.deviation_angles.back() / units::degree) << " deg, T from " << fmt(m.temperatures.front()) << " to "
          << fmt(m.temperatures.back()) << " degC.\n\n";
      std::size_t sat0 = 0, satr = 0;
      for (const auto &p : m.points)
        {
          sat0 += p.displacement_saturated;
          satr += p.pressure_saturated;
        }
      out << "Saturated points (flapper on a nozzle, spool on a stop, or the spool in another regime than at the "
             "reference point, e.g. lifted from vented into its lap): "
          << sat0 << " of " << m.points.size() << " at i = 0, " << satr << " of " << m.points.size()
          << " at the rated current. A saturated deviation measures the limit, not the valve (C8); such values are "
             "marked * below and flagged in system/drift_map.csv.\n\n";

      const auto t40 = temperature_index(m, 40), t50 = temperature_index(m, 50), t110 = temperature_index(m, 110),
                 t120 = temperature_index(m, 120);
      const std::size_t a_max = m.deviation_angles.size() - 1;
      out << "At the largest deviation angle, theta_d = " << fmt(m.deviation_angles[a_max] / units::degree)
          << " deg, beside the paper at theta_d = 1 deg (model.md section 3 items 11, 12; C9: the paper's drift curves "
             "are a comparison, not a target):\n\n";
      if (!(t40 && t50 && t110 && t120))
        {
          out << "(the drift temperatures do not include 40, 50, 110 and 120 degC; see system/drift_map.csv)\n\n";
          return;
        }
      auto row = [&](const char *name, const char *unit, double scale, double (*get)(const DriftPoint &),
                     const double paper[4], double paper_ratio, bool (*is_saturated)(const DriftPoint &)) {
        const DriftPoint *p[4] = {&m.at(*t40, a_max), &m.at(*t50, a_max), &m.at(*t110, a_max), &m.at(*t120, a_max)};
        double v[4];
        std::string cells[4];
        for (int k = 0; k < 4; ++k)
          {
            v[k] = get(*p[k]);
            cells[k] = fmt(v[k] * scale) + (is_saturated(*p[k]) ? "*" : "");
          }
        const double s_low = (v[1] - v[0]) / 10, s_high = (v[3] - v[2]) / 10;
        out << "| " << name << " [" << unit << "] | servodrift | " << cells[0] << " | " << cells[1] << " | " << cells[2]
            << " | " << cells[3] << " | " << fmt(s_low * scale) << " | " << fmt(s_high * scale) << " | "
            << (s_high != 0 ? fmt(s_low / s_high, 3) : "n/a") << " |\n";
        out << "| | paper | " << fmt(paper[0] * scale) << " | " << fmt(paper[1] * scale) << " | " << fmt(paper[2] * scale)
            << " | " << fmt(paper[3] * scale) << " | " << fmt((paper[1] - paper[0]) / 10 * scale) << " | "
            << fmt((paper[3] - paper[2]) / 10 * scale) << " | " << fmt(paper_ratio, 3) << " |\n";
      };
      out << "| measure | | 40 degC | 50 degC | 110 degC | 120 degC | secant slope 40-50 /degC | secant slope 110-120 "
             "/degC | slope ratio |\n|---|---|---|---|---|---|---|---|---|\n";
      static const double paper_x[4] = {5.68e-4, 4.24e-4, 1.60e-4, 1.48e-4};
      static const double paper_p[4] = {4.49e4, 3.35e4, 1.27e4, 1.16e4};
      row("spool displacement deviation, i = 0", "um", 1e6,
          [](const DriftPoint &p) { return p.spool_displacement_deviation; }, paper_x, 11.5,
          [](const DriftPoint &p) { return p.displacement_saturated; });
      row("brake pressure deviation, rated current", "kPa", 1e-3,
          [](const DriftPoint &p) { return p.brake_pressure_deviation; }, paper_p, 10.4,
          [](const DriftPoint &p) { return p.pressure_saturated; });
      if (m.nulled_at_reference)
        {
          static const double nothing[4] = {std::nan(""), std::nan(""), std::nan(""), std::nan("")};
          row("brake pressure deviation, own drift removed (C8)", "kPa", 1e-3,
              [](const DriftPoint &p) { return p.brake_pressure_deviation_own_drift_removed; }, nothing, std::nan(""),
              [](const DriftPoint &p) { return p.pressure_saturated; });
          row("pilot null pressure shift p_L - p_R, i = 0", "kPa", 1e-3,
              [](const DriftPoint &p) { return p.null_pressure_shift; }, nothing, std::nan(""),
              [](const DriftPoint &p) { return p.zero_current.flapper != FlapperState::free; });
        }
      out << "\nThe paper's slopes are tangents: 1.44e-5 m/degC and 1.25e-6 m/degC, 1.14e3 Pa/degC and 110 Pa/degC. "
          << "servodrift's tangent slopes at 40 and 120 degC: spool "
          << fmt(m.at(*t40, a_max).spool_displacement_deviation_slope) << " and "
          << fmt(m.at(*t120, a_max).spool_displacement_deviation_slope) << " m/degC, brake pressure "
          << fmt(m.at(*t40, a_max).brake_pressure_deviation_slope) << " and "
          << fmt(m.at(*t120, a_max).brake_pressure_deviation_slope) << " Pa/degC.\n\n";
      if (!m.nulled_at_reference)
        {
          const double d40 = m.at(*t40, a_max).brake_pressure_deviation, d120 = m.at(*t120, a_max).brake_pressure_deviation;
          out << "Scale-free (D9): delta p_B(120)/delta p_B(40) = " << (d40 != 0 ? fmt(d120 / d40, 3) : "n/a")
              << " (paper 0.258); delta x_v(120)/delta x_v(40) = "
              << (m.at(*t40, a_max).spool_displacement_deviation != 0 ?
                    fmt(m.at(*t120, a_max).spool_displacement_deviation / m.at(*t40, a_max).spool_displacement_deviation, 3) :
                    "n/a")
              << " (paper 0.261).\n\n";
        }
      else
        out << "Scale-free (D9, C8): delta(T)/delta(40) is undefined here because every valve is nulled at 40 degC; "
               "the slope ratio above is the scale-free measure.\n\n";
      const auto &p40 = m.at(*t40, a_max), &p120 = m.at(*t120, a_max);
      auto current = [&](const DriftPoint &p) {
        const double i = p.null_shift_current ? shown_current(*p.null_shift_current) : 0.0;
        return p.null_shift_current ? fmt(i * 1e3) + " mA (" + fmt(100 * i / valve.operating.rated_current) +
                                        " % of rated)" :
                                      std::string("beyond the torque table's currents");
      };
      out << "Null-shift current (C8, the primary zero-current measure) at theta_d = "
          << fmt(m.deviation_angles[a_max] / units::degree) << " deg: " << current(p40) << " at 40 degC, " << current(p120)
          << " at 120 degC. Pilot null pressure shift p_L - p_R at i = 0: " << fmt(p40.null_pressure_shift * 1e-3)
          << " kPa at 40 degC, " << fmt(p120.null_pressure_shift * 1e-3) << " kPa at 120 degC.\n\n";
    }

    /// The drift map's null-shift current against `Tolerances/Null-shift spec' (a band over T): at
    /// the table temperatures among the drift temperatures and the two largest deviation angles of
    /// either sign, and whether every point of the map is within it.
    void null_shift_against_spec(std::ostream &out, const ValveDescription &valve, const DriftMap &m)
    {
      const auto &t = valve.tolerances;
      const double T0 = valve.operating.reference_temperature, rated = valve.operating.rated_current;
      std::size_t beyond = 0, unknown = 0;
      std::string first;
      for (std::size_t k = 0; k < m.temperatures.size(); ++k)
        for (std::size_t a = 0; a < m.deviation_angles.size(); ++a)
          {
            const auto &i = m.at(k, a).null_shift_current;
            if (!i)
              ++unknown;
            else if (!t.within_null_shift_spec(*i, m.temperatures[k], rated, T0) && beyond++ == 0)
              first = fmt(100 * *i / rated) + " % at " + fmt(m.temperatures[k]) + " degC, theta_d = " +
                      fmt(m.deviation_angles[a] / units::degree) + " deg, where " +
                      fmt(100 * t.null_shift_limit(m.temperatures[k], T0)) + " % is allowed";
          }
      out << "Null-shift current against the spec |null-shift current| <= " << t.null_shift_spec_text(T0)
          << " (`Tolerances/Null-shift spec`): ";
      if (beyond == 0 && unknown == 0)
        out << "**within** it at every drift temperature and deviation angle.\n\n";
      else
        out << "**beyond** it at " << beyond << " of " << m.points.size() << " points of the map"
            << (beyond ? " (the first: " + first + ")" : std::string()) << (unknown ? ", " + std::to_string(unknown) +
               " without a null within the torque table's currents" : std::string()) << ".\n\n";
      const std::size_t a_low = 0, a_high = m.deviation_angles.size() - 1;
      out << "| T [degC] | allowed [% of rated] | at theta_d = " << fmt(m.deviation_angles[a_low] / units::degree)
          << " deg [% of rated] | at theta_d = " << fmt(m.deviation_angles[a_high] / units::degree)
          << " deg [% of rated] |\n|---|---|---|---|\n";
      const auto &tables = valve.sweeps.table_temperatures;
      const auto cell = [&](const DriftPoint &p) {
        if (!p.null_shift_current)
          return std::string("n/a");
        const double i = shown_current(*p.null_shift_current);
        return fmt(100 * i / rated, 3);
      };
      for (std::size_t k = 0; k < m.temperatures.size(); ++k)
        if (std::find(tables.begin(), tables.end(), m.temperatures[k]) != tables.end())
          out << "| " << fmt(m.temperatures[k]) << " | " << fmt(100 * t.null_shift_limit(m.temperatures[k], T0), 3)
              << " | " << cell(m.at(k, a_low)) << " | " << cell(m.at(k, a_high)) << " |\n";
      out << "\nEvery drift temperature: `system/drift_map.csv`; plot `null_shift_current_lines` with the spec's "
             "band.\n\n";
    }
  } // namespace

  void write_report(const ValveDescription &valve, const SystemResults &r, const PlotFiles &plots, const std::string &path)
  {
    std::ostringstream out;
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof(date), "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    out << "# servodrift report\n\n"
        << "- producer: " << producer_string("") << "\n- date: " << date << "\n- valve description: " << valve.source
        << " (parameters sha256 `" << valve.parameters_sha256.substr(0, 16) << "`, full file in `parameters.prm`)\n";
    for (const auto &p : r.table_producers)
      out << "- table " << p << "\n";
    for (const auto &w : r.warnings)
      out << "- **warning**: " << w << "\n";
    for (const auto &n : r.notes)
      out << "- note: " << n << "\n";
    out << "\nmodel.md columns are the values of the built-in valve RV-1 (model.md section 2 and clarifications C1-C3); "
           "they apply to this run only if its valve is RV-1.\n\n";

    out << "## Stage coefficients\n\n";
    stage_table(out, r);
    out << "Every temperature: `system/stage_coefficients.csv`. Fits (E25-E28 and full polynomials): "
           "`tables/fits.json`; E28 here: K_f(T) over the paper's 40-120 degC (where the drift temperatures reach "
           "it) with R^2 = "
        << fmt(r.flow_force_fit.r_squared, 6) << ".\n\n";

    out << "## Operating points\n\n";
    operating_points(out, r.drift_map);

    out << "## Drift maps\n\n";
    drift_section(out, valve, r.drift_map);
    out << "Every point: `system/drift_map.csv`.\n\n";
    null_shift_against_spec(out, valve, r.drift_map);

    if (r.dynamics)
      dynamics_section(out, valve, *r.dynamics);
    else
      out << "## Dynamics\n\nNot computed in this run (`Dynamics/Enabled`, or `servodrift dynamics`).\n\n";
    if (r.calibration)
      calibration_section(out, *r.calibration);
    if (r.tolerances)
      tolerance_section(out, valve, *r.tolerances);
    else
      out << "## Tolerances\n\nNot computed in this run (`Tolerances/Enabled`, or `servodrift tolerances`).\n\n";
    model_form_section(out, r.model_form);

    out << "## Plots\n\n";
    for (const auto &image : plots.images)
      if (image.size() > 4 && image.substr(image.size() - 4) == ".png")
        out << "![" << image << "](" << image << ")\n\n";
    if (!plots.problem.empty())
      out << plots.problem << "\n\n";

    out << "## Files\n\n"
        << "- `parameters.prm`: the valve description as used\n"
        << "- `tables/*.csv`: coefficient tables; `tables/fits.json`: fits\n"
        << "- `system/stage_coefficients.csv`, `system/operating_points.csv`, `system/drift_map.csv`\n"
        << (r.dynamics ? "- `system/modes.csv`, `system/frequency_response.csv`, `system/step_response.csv`, "
                         "`system/step_metrics.csv`, `system/sine_response.csv`, `system/dynamics_summary.csv`" +
                           std::string(r.dynamics->fixed_time.empty() ? "" : ", `system/fixed_time_study.csv`") + "\n" :
                         "")
        << (r.tolerances ? std::string("- `system/tolerance_samples.csv`, `system/tolerance_summary.csv`") +
                             (r.tolerances->sobol ? ", `system/sobol_indices.csv`" : "") + "\n" :
                           std::string())
        << "- `system/plots/`: images, their data (`.dat`) and gnuplot scripts (`.gp`)\n";
    write_file_atomically(path, out.str());
  }
} // namespace servodrift::system
