// The checks of the asymmetric valve and of the tolerance study that go beyond one entry's range
// (declared in valve_description.h): physical left and right parts, distributions that contain the
// nominal valve, a positive definite correlation matrix (issue 25). All before any stage runs.
#include "common/error.h"
#include "common/thermal_laws.h"
#include "common/valve_description.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace servodrift
{
  namespace
  {
    [[noreturn]] void refuse(const std::string &entry, const std::string &what)
    {
      throw InputError("`" + entry + "' " + what);
    }

    /// The smallest nominal x0(T) over the drift temperatures and T0 [m].
    double smallest_null_gap(const ValveDescription &v)
    {
      const double T0 = v.operating.reference_temperature;
      double x0 = laws::pilot_stage_geometry(v.pilot, v.armature, v.expansion, T0, T0).null_gap;
      for (double T : v.sweeps.drift_temperatures)
        x0 = std::min(x0, laws::pilot_stage_geometry(v.pilot, v.armature, v.expansion, T, T0).null_gap);
      return x0;
    }

    /// The nominal value that a toleranced quantity deviates from, and the smallest value that keeps
    /// the part physical (> 0 for sizes and factors); an angle or a mismatch has no such bound.
    struct Nominal
    {
      double value;
      bool must_stay_positive;
    };
    Nominal nominal_of(const ValveDescription &v, std::size_t quantity)
    {
      const auto &a = v.asymmetry;
      switch (quantity)
        {
          case 0: return {v.pilot.fixed_orifice_diameter + a.left.orifice_diameter, true};
          case 1: return {v.pilot.fixed_orifice_diameter + a.right.orifice_diameter, true};
          case 2: return {v.pilot.nozzle_diameter + a.left.nozzle_diameter, true};
          case 3: return {v.pilot.nozzle_diameter + a.right.nozzle_diameter, true};
          case 4: return {smallest_null_gap(v) + a.left.null_gap, true};
          case 5: return {smallest_null_gap(v) + a.right.null_gap, true};
          case 6: return {a.left.orifice_discharge_factor, true};
          case 7: return {a.right.orifice_discharge_factor, true};
          case 8: return {a.left.nozzle_discharge_factor, true};
          case 9: return {a.right.nozzle_discharge_factor, true};
          case 13: return {1 + a.left_remanence, true};
          case 14: return {1 + a.right_remanence, true};
          default: return {0, false};
        }
    }
  } // namespace

  void validate_asymmetry(const ValveDescription &v)
  {
    const auto &a = v.asymmetry;
    const double x0 = smallest_null_gap(v);
    for (const bool left : {true, false})
      {
        const SideDeviations &d = left ? a.left : a.right;
        const std::string side = left ? "Asymmetry/Left " : "Asymmetry/Right ";
        if (!(v.pilot.fixed_orifice_diameter + d.orifice_diameter > 0))
          refuse(side + "orifice diameter deviation", "= " + format_number(d.orifice_diameter) +
                                                        " m leaves no orifice: it must be > -" +
                                                        format_number(v.pilot.fixed_orifice_diameter) + " m");
        if (!(v.pilot.nozzle_diameter + d.nozzle_diameter > 0))
          refuse(side + "nozzle diameter deviation", "= " + format_number(d.nozzle_diameter) +
                                                       " m leaves no nozzle: it must be > -" +
                                                       format_number(v.pilot.nozzle_diameter) + " m");
        if (!(x0 + d.null_gap > 0))
          refuse(side + "null gap deviation", "= " + format_number(d.null_gap) +
                                                " m closes the gap at x_f = 0: it must be > -" + format_number(x0) +
                                                " m, the smallest null gap x0(T) over the drift temperatures");
      }
  }

  void validate_null_shift_spec(const ValveDescription &v)
  {
    const auto &t = v.tolerances;
    if (!(t.null_shift_spec > 0))
      refuse("Tolerances/Null-shift spec", "= 0 % must be > 0 (allowed: (0, 100] % of the rated current)");
    if (t.null_shift_spec_form != ToleranceParameters::SpecForm::table)
      return;
    const auto &table = t.null_shift_spec_table;
    const std::string entry = "Tolerances/Null-shift spec table";
    if (table.size() < 2)
      refuse(entry, "has " + std::to_string(table.size()) + " pairs; `Null-shift spec form' = table needs at least 2");
    for (std::size_t k = 0; k < table.size(); ++k)
      {
        if (k > 0 && !(table[k].first > table[k - 1].first))
          refuse(entry, "has " + format_number(table[k].first) + " degC after " + format_number(table[k - 1].first) +
                          " degC: the temperatures must be strictly increasing");
        if (!(table[k].second >= 0 && table[k].second <= 1))
          refuse(entry, "allows " + format_number(100 * table[k].second) + " % at " + format_number(table[k].first) +
                          " degC (allowed: 0 to 100 % of the rated current)");
      }
    const auto &drift = v.sweeps.drift_temperatures;
    if (drift.front() < table.front().first || drift.back() > table.back().first)
      refuse(entry, "covers " + format_number(table.front().first) + " to " + format_number(table.back().first) +
                      " degC, not the drift temperatures' " + format_number(drift.front()) + " to " +
                      format_number(drift.back()) + " degC (`Sweeps/Drift temperatures')");
  }

  void validate_tolerances(const ValveDescription &v)
  {
    const auto &t = v.tolerances;
    if (t.sobol_base_samples > 0 && t.sobol_base_samples < 64)
      refuse("Tolerances/Sobol base samples", "= " + std::to_string(t.sobol_base_samples) +
                                                " is too few for an estimate with a bootstrap interval (allowed: 0, "
                                                "no Sobol' study, or at least 64)");
    const auto &names = ToleranceParameters::quantities();
    const auto active = t.active();
    if (active.empty())
      refuse("Tolerances", "has no toleranced quantity: set `Distribution' in at least one of its subsections "
                           "(e.g. `Tolerances/Left orifice diameter/Distribution' = normal)");
    for (const std::size_t q : active)
      {
        const ToleranceDistribution &d = t.distributions[q];
        const std::string entry = "Tolerances/" + d.name + "/";
        using Kind = ToleranceDistribution::Kind;
        if ((d.kind == Kind::normal || d.kind == Kind::truncated_normal) && !(d.standard_deviation > 0))
          refuse(entry + "Standard deviation", "= 0 " + d.unit + " must be > 0 for a normal distribution");
        if (d.kind == Kind::uniform || d.kind == Kind::truncated_normal)
          {
            if (!(d.lower < d.upper))
              refuse(entry + "Lower bound", "= " + format_number(d.lower) + " " + d.unit + " must be below `" + entry +
                                              "Upper bound' = " + format_number(d.upper) + " " + d.unit);
            if (!(d.lower <= 0 && d.upper >= 0))
              refuse(entry + (d.lower > 0 ? "Lower bound" : "Upper bound"),
                     "excludes the nominal value: the interval [" + format_number(d.lower) + ", " +
                       format_number(d.upper) + "] " + d.unit + " of the deviation must contain 0");
          }
        // Every drawn valve physical: the lowest value (6 standard deviations for a normal) > 0
        const Nominal n = nominal_of(v, q);
        if (n.must_stay_positive)
          {
            const double lowest = d.kind == Kind::normal ? d.mean - 6 * d.standard_deviation : d.lower;
            if (!(n.value + lowest > 0))
              refuse(entry + (d.kind == Kind::normal ? "Standard deviation" : "Lower bound"),
                     "lets the part reach " + format_number(n.value + lowest) + " " + d.unit +
                       " (nominal " + format_number(n.value) + " " + d.unit +
                       (d.kind == Kind::normal ? " - 6 standard deviations" : " + lower bound") + "): it must stay > 0");
          }
      }

    // Correlations: between toleranced quantities, and a positive definite matrix
    Eigen::MatrixXd R = Eigen::MatrixXd::Identity(active.size(), active.size());
    for (const auto &c : t.correlations)
      {
        const auto i = std::find(active.begin(), active.end(), c.first), j = std::find(active.begin(), active.end(), c.second);
        if (i == active.end() || j == active.end())
          refuse("Tolerances/Correlations", "correlates `" + names[i == active.end() ? c.first : c.second].first +
                                              "', which has no distribution (set its `Distribution')");
        R(i - active.begin(), j - active.begin()) = R(j - active.begin(), i - active.begin()) = c.coefficient;
      }
    if (!t.correlations.empty())
      {
        const Eigen::LLT<Eigen::MatrixXd> llt(R);
        if (llt.info() != Eigen::Success || !(llt.matrixL().toDenseMatrix().diagonal().minCoeff() > 1e-8))
          {
            // the pair that weighs most in the direction of the smallest eigenvalue: the one to change
            const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(R);
            const Eigen::VectorXd v = eigen.eigenvectors().col(0).cwiseAbs();
            Eigen::Index a = 0, b = 0;
            v.maxCoeff(&a);
            Eigen::VectorXd rest = v;
            rest(a) = -1;
            rest.maxCoeff(&b);
            refuse("Tolerances/Correlations",
                   "give a correlation matrix that is not positive definite (smallest eigenvalue " +
                     format_number(eigen.eigenvalues()(0)) + "): `" + names[active[std::size_t(a)]].first + "' : `" +
                     names[active[std::size_t(b)]].first + "' : " + format_number(R(a, b)) +
                     " contradicts the others (allowed: the matrix of a real joint distribution)");
          }
        if (t.sobol_base_samples > 0)
          refuse("Tolerances/Sobol base samples", "must be 0 with `Tolerances/Correlations' set: Sobol' indices "
                                                  "need independent quantities (allowed: 0, or no correlations)");
      }
  }
} // namespace servodrift
