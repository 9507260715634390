#include "system/calibration.h"

#include "common/error.h"
#include "common/parameter_input.h"
#include "system/calibration_identifiability.h"
#include "system/calibration_model.h"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <ceres/ceres.h>
#include <glog/logging.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace servodrift::system
{
  namespace
  {
    /// Ceres reports through glog, which before InitGoogleLogging writes every message, with a
    /// warning that it was not initialised, to stderr. servodrift reports the solver's outcome
    /// itself (the termination message, the warnings): glog initialised once, to log nothing below
    /// FATAL and no files.
    void quiet_solver_logging()
    {
      if (google::IsGoogleLoggingInitialized())
        return;
      FLAGS_logtostderr = true;       // no log files in /tmp
      FLAGS_minloglevel = google::GLOG_FATAL;
      google::InitGoogleLogging("servodrift");
    }

    /// Subsections that hold no valve parameter: what they set is how a run samples or writes.
    const std::set<std::string> not_valve_parameters = {"Output", "Sweeps", "Flow solver", "Fits", "Dynamics", "Tolerances"};

    FreeParameter free_parameter(const CalibrationRequest &request, const std::string &text)
    {
      const auto equals = text.find('=');
      const std::string path = current_entry_path(text.substr(0, equals), "--free \"" + shown_input(text) + "\"");
      const std::string subsection = path.substr(0, path.find('/'));
      if (not_valve_parameters.count(subsection))
        throw InputError("--free \"" + shown_input(text) + "\": `" + subsection +
                         "' holds no valve parameter (allowed: entries of the valve's subsections, e.g. `Offsets', "
                         "`Asymmetry', `Spool')");
      const NumericEntry e = numeric_entry(request.input_file, request.overrides, path);
      FreeParameter p{path, e.unit, e.value, e.lower, e.upper};
      if (equals != std::string::npos)
        {
          const std::string bounds = text.substr(equals + 1);
          const auto colon = bounds.find(':');
          char *end_lo = nullptr, *end_hi = nullptr;
          const std::string lo = bounds.substr(0, colon), hi = colon == std::string::npos ? "" : bounds.substr(colon + 1);
          p.lower = std::strtod(lo.c_str(), &end_lo);
          p.upper = std::strtod(hi.c_str(), &end_hi);
          if (colon == std::string::npos || lo.empty() || hi.empty() || *end_lo || *end_hi || !std::isfinite(p.lower) ||
              !std::isfinite(p.upper))
            throw InputError("--free \"" + shown_input(text) + "\": bounds must be `lower:upper' (numbers in " + e.unit + ")");
          if (!(p.lower < p.upper && p.lower >= e.lower && p.upper <= e.upper))
            throw InputError("--free \"" + shown_input(text) + "\": bounds must satisfy " + format_number(e.lower) +
                             " <= lower < upper <= " + format_number(e.upper) + " " + e.unit + " (the declared range)");
        }
      if (!(p.initial >= p.lower && p.initial <= p.upper))
        throw InputError("--free \"" + shown_input(text) + "\": the starting value " + format_number(p.initial) + " " +
                         e.unit + " lies outside the bounds");
      return p;
    }

    /// "`Offsets/Magnetic null' = 2 deg, ...": the free entries at `values' (declared units).
    std::string describe(const std::vector<FreeParameter> &parameters, const std::vector<double> &values)
    {
      std::string text;
      for (std::size_t j = 0; j < parameters.size(); ++j)
        text += (j ? ", `" : "`") + parameters[j].path + "' = " + format_number(values[j]) + " " + parameters[j].unit;
      return text;
    }

    /// Weighted residuals (model - measured)/sigma of the free parameters in scaled form,
    /// value = initial + scale x, with central differences (one-sided at a bound).
    class Residuals final : public ceres::CostFunction
    {
    public:
      Residuals(const CalibrationModel &model_, const CalibrationSetup &setup_, std::vector<Measurement> points_,
                std::vector<double> sigma_, std::vector<double> scale_, std::vector<double> lower_,
                std::vector<double> upper_)
        : model(model_)
        , setup(setup_)
        , points(std::move(points_))
        , sigma(std::move(sigma_))
        , scale(std::move(scale_))
        , lower(std::move(lower_))
        , upper(std::move(upper_))
      {
        set_num_residuals(int(points.size()));
        mutable_parameter_block_sizes()->push_back(int(scale.size()));
      }

      std::vector<double> values(const double *x) const
      {
        std::vector<double> v;
        for (std::size_t j = 0; j < scale.size(); ++j)
          v.push_back(setup.parameters[j].initial + scale[j] * x[j]);
        return v;
      }

      /// The weighted residuals at scaled x; false where the model refuses the values (the last
      /// refusal is kept: refusal()).
      bool residuals_at(const double *x, double *r) const
      {
        try
          {
            const std::vector<double> y = model.predict(values(x), points);
            for (std::size_t k = 0; k < y.size(); ++k)
              r[k] = (y[k] - points[k].value) / sigma[k];
            return true;
          }
        catch (const std::exception &e)
          {
            last_refusal = describe(setup.parameters, values(x)) + ": " + e.what();
            return false;
          }
      }

      /// The model's last refusal of a trial point, with the free entries' values there.
      const std::string &refusal() const { return last_refusal; }

      bool Evaluate(double const *const *parameters, double *r, double **jacobians) const override
      {
        const double *x = parameters[0];
        if (!residuals_at(x, r))
          return false;
        if (jacobians == nullptr || jacobians[0] == nullptr)
          return true;
        // step: 1e-4 of a parameter's scale (1e-3 of its range or its magnitude). The residuals
        // carry the root finders' rounding, about 1e-12 relative; the central difference's error
        // h^2 f'''/6 + eps/h is then near 1e-8 relative, far below any standard error.
        const std::size_t n = points.size(), p = scale.size();
        std::vector<double> xp(x, x + p), plus(n), minus(n);
        for (std::size_t j = 0; j < p; ++j)
          {
            const double h = 1e-4;
            const double a = std::max(lower[j], x[j] - h), b = std::min(upper[j], x[j] + h);
            xp[j] = b;
            if (!residuals_at(xp.data(), plus.data()))
              return false;
            xp[j] = a;
            if (!residuals_at(xp.data(), minus.data()))
              return false;
            xp[j] = x[j];
            for (std::size_t k = 0; k < n; ++k)
              jacobians[0][k * p + j] = (plus[k] - minus[k]) / (b - a);
          }
        return true;
      }

    private:
      const CalibrationModel &model;
      const CalibrationSetup &setup;
      std::vector<Measurement> points;
      std::vector<double> sigma, scale, lower, upper;
      mutable std::string last_refusal;
    };

    /// The size of the measured values (their RMS; the start's residuals' where all are zero; 1
    /// where those are too), in their SI unit: a first estimate of an unknown common sigma.
    double data_scale(const CalibrationModel &model, const CalibrationSetup &setup)
    {
      double values = 0, residuals = 0;
      for (const auto &m : setup.data.points)
        values += m.value * m.value;
      if (values > 0)
        return std::sqrt(values / double(setup.data.points.size()));
      std::vector<double> start;
      for (const auto &q : setup.parameters)
        start.push_back(q.initial);
      for (double y : model.predict(start, setup.data.points))
        residuals += y * y;
      return residuals > 0 ? std::sqrt(residuals / double(setup.data.points.size())) : 1.0;
    }

  } // namespace

  CalibrationSetup prepare_calibration(const CalibrationRequest &request, const StageTables &tables)
  {
    CalibrationSetup s;
    std::set<std::string> seen;
    for (const auto &text : request.free)
      {
        s.parameters.push_back(free_parameter(request, text));
        if (!seen.insert(s.parameters.back().path).second)
          throw InputError("--free \"" + shown_input(text) + "\" is given twice");
      }
    if (s.parameters.empty())
      throw InputError("calibrate: no free parameter (give --free \"Subsection/Key\", e.g. --free \"Offsets/Magnetic null\")");
    s.data = read_measured_data(request.measured_file);
    const std::size_t n = s.data.points.size(), p = s.parameters.size();
    if (n < p || (!s.data.standard_deviations_given && n == p))
      throw InputError(shown_input(request.measured_file) + ": " + std::to_string(n) + " measured values for " +
                       std::to_string(p) + " free parameters (need at least " + std::to_string(p) +
                       (s.data.standard_deviations_given ? "" : " + 1, as the noise is estimated from the fit") + ")");
    std::set<MeasuredQuantity> quantities;
    for (const auto &m : s.data.points)
      quantities.insert(m.quantity);
    if (!s.data.standard_deviations_given && quantities.size() > 1)
      throw InputError(shown_input(request.measured_file) +
                       ": several measured quantities without standard deviations: their weights cannot be guessed "
                       "(add a <quantity>_sd[unit] column for each)");
    const StageFunctions f(tables);
    const auto &T = f.torque.axis(0), &i = f.torque.axis(2);
    for (const auto &m : s.data.points)
      {
        if (m.temperature < T.front() || m.temperature > T.back())
          throw InputError(shown_input(request.measured_file) + ":" + std::to_string(m.line) + ": temperature " +
                           format_number(m.temperature) + " degC lies outside the tables' " + format_number(T.front()) +
                           " to " + format_number(T.back()) + " degC (`Sweeps/Table temperatures')");
        if (m.current < i.front() || m.current > i.back())
          throw InputError(shown_input(request.measured_file) + ":" + std::to_string(m.line) + ": current " +
                           format_number(m.current) + " A lies outside the torque table's " + format_number(i.front()) +
                           " to " + format_number(i.back()) + " A (`Sweeps/Motor currents')");
      }
    // the model at the starting values: a point it cannot reach is refused now, not mid-fit
    const CalibrationModel model(request, s.parameters, tables);
    std::vector<double> start;
    for (const auto &q : s.parameters)
      start.push_back(q.initial);
    try
      {
        model.predict(start, s.data.points);
      }
    catch (const std::exception &e)
      {
        throw InputError("calibrate: the start " + describe(s.parameters, start) + " is outside the model: " + e.what());
      }
    return s;
  }

  CalibrationResults calibrate(const CalibrationRequest &request, const CalibrationSetup &setup, const StageTables &tables)
  {
    CalibrationResults r;
    r.request = request;
    r.setup = setup;
    const std::size_t n = setup.data.points.size(), p = setup.parameters.size();
    const CalibrationModel model(request, setup.parameters, tables);
    r.sigma_estimated = !setup.data.standard_deviations_given;
    // Without standard deviations the points share one unknown sigma (one quantity): any common
    // weight gives the same fit, but Ceres' gradient tolerance is absolute, so residuals in SI
    // units (amperes) would stop it early. A first estimate of sigma, the measured values' own
    // size, makes the residuals O(1) and the solver's tolerances relative.
    const double first_sigma = r.sigma_estimated ? data_scale(model, setup) : 1.0;
    for (const auto &m : setup.data.points)
      r.weights.push_back(r.sigma_estimated ? first_sigma : m.standard_deviation);

    // scaled parameters: value = initial + scale x, scale a thousandth of the range or the value
    std::vector<double> scale, lower, upper;
    for (const auto &q : setup.parameters)
      {
        scale.push_back(std::max(std::abs(q.initial), 1e-3 * (q.upper - q.lower)));
        lower.push_back((q.lower - q.initial) / scale.back());
        upper.push_back((q.upper - q.initial) / scale.back());
      }
    auto *residuals = new Residuals(model, setup, setup.data.points, r.weights, scale, lower, upper);
    std::vector<double> x(p, 0.0);
    ceres::Problem problem;
    problem.AddResidualBlock(residuals, nullptr, x.data());
    for (std::size_t j = 0; j < p; ++j)
      {
        problem.SetParameterLowerBound(x.data(), int(j), lower[j]);
        problem.SetParameterUpperBound(x.data(), int(j), upper[j]);
      }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = 200;
    options.function_tolerance = 1e-15;
    options.gradient_tolerance = 1e-15;
    options.parameter_tolerance = 1e-12;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    quiet_solver_logging();
    ceres::Solve(options, &problem, &summary);
    r.termination = summary.message;
    r.iterations = int(summary.iterations.size()) - 1;
    if (!summary.IsSolutionUsable())
      throw InputError("calibrate: stuck at " + describe(setup.parameters, residuals->values(x.data())) +
                       (residuals->refusal().empty() ? ": " + summary.message :
                                                       "; the model refuses every step, last at " + residuals->refusal()));
    if (summary.termination_type == ceres::NO_CONVERGENCE)
      r.warnings.push_back("the solver stopped after " + std::to_string(r.iterations) +
                           " iterations without converging: " + summary.message);
    r.estimates = residuals->values(x.data());

    // residuals and Jacobian at the estimate
    Eigen::VectorXd res(n);
    Jacobian J(n, p);
    {
      const double *parameters[] = {x.data()};
      double *jacobians[] = {J.data()};
      if (!residuals->Evaluate(parameters, res.data(), jacobians))
        throw std::runtime_error("calibrate: the model fails at the estimate");
    }
    const std::vector<double> fit_sigma = r.weights;
    const Identifiability id = identifiability(J);
    r.rank = id.rank;
    r.degrees_of_freedom = n - id.rank;
    const double s2 = r.degrees_of_freedom > 0 ? res.squaredNorm() / double(r.degrees_of_freedom) : 0.0;
    // with sigma estimated, chi-square and its reduced value are in SI units squared: the latter
    // is the residuals' variance that the intervals assume
    const double unit_square = first_sigma * first_sigma;
    r.chi_square = res.squaredNorm() * unit_square;
    r.reduced_chi_square = s2 * unit_square;
    if (r.sigma_estimated) // one quantity without standard deviations: sigma = the residuals' scatter
      for (double &w : r.weights)
        w = std::sqrt(s2) * first_sigma;

    std::vector<int> constant;
    for (std::size_t j = 0; j < p; ++j)
      if (!id.identifiable[j])
        {
          constant.push_back(int(j));
          r.not_identifiable.push_back(setup.parameters[j].path);
        }
    r.determined = determined_combinations(id, setup.parameters, scale, r.estimates, r.sigma_estimated ? s2 : 1.0);
    if (!r.not_identifiable.empty())
      {
        std::string list, determined;
        for (const auto &path : r.not_identifiable)
          list += (list.empty() ? "`" : ", `") + path + "'";
        for (const auto &c : r.determined)
          determined += (determined.empty() ? "; the data determine " : " and ") + c.text() + " = " +
                        format_number(c.estimate) + " +- " + format_number(c.standard_error) + " " + c.unit;
        r.warnings.push_back("the data cannot tell apart (or do not depend on) " + list +
                             ": their estimates are one of many that fit equally, without standard errors" +
                             determined + "; fix all but one or add measurements that separate them");
      }

    // Covariance of the identifiable ones (Ceres, dense SVD), the others held constant
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
    if (constant.size() < p)
      {
        if (!constant.empty())
          problem.SetManifold(x.data(), new ceres::SubsetManifold(int(p), constant));
        ceres::Covariance::Options covariance_options;
        covariance_options.algorithm_type = ceres::DENSE_SVD;
        covariance_options.null_space_rank = -1;
        ceres::Covariance covariance(covariance_options);
        std::vector<std::pair<const double *, const double *>> blocks = {{x.data(), x.data()}};
        if (!covariance.Compute(blocks, &problem))
          throw std::runtime_error("calibrate: the covariance of the estimates could not be computed");
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> block(p, p);
        covariance.GetCovarianceBlock(x.data(), x.data(), block.data());
        C = block;
        if (r.sigma_estimated)
          C *= s2;
      }
    r.interval_factor = r.sigma_estimated ?
                          boost::math::quantile(boost::math::students_t(double(r.degrees_of_freedom)), 0.975) :
                          boost::math::quantile(boost::math::normal(), 0.975);
    r.correlation.assign(p, std::vector<double>(p, 0.0));
    for (std::size_t j = 0; j < p; ++j)
      {
        r.correlation[j][j] = 1;
        if (!id.identifiable[j])
          {
            r.standard_errors.push_back(std::nullopt);
            r.intervals.push_back(std::nullopt);
            continue;
          }
        const double se = scale[j] * std::sqrt(std::max(0.0, C(j, j)));
        r.standard_errors.push_back(se);
        r.intervals.push_back(Interval{r.estimates[j] - r.interval_factor * se, r.estimates[j] + r.interval_factor * se});
        for (std::size_t k = 0; k < p; ++k)
          if (k != j && id.identifiable[k] && C(j, j) > 0 && C(k, k) > 0)
            r.correlation[j][k] = C(j, k) / std::sqrt(C(j, j) * C(k, k));
      }
    for (std::size_t j = 0; j < p; ++j)
      for (std::size_t k = j + 1; k < p; ++k)
        if (std::abs(r.correlation[j][k]) > 0.99)
          r.warnings.push_back("`" + setup.parameters[j].path + "' and `" + setup.parameters[k].path +
                               "' are correlated by " + format_number(r.correlation[j][k]) +
                               ": the data barely tell them apart");

    // the model and its standard deviation from the parameters' covariance (C in the scaled
    // coordinates, the Jacobian of the weighted residuals): at each point, then along temperature
    for (std::size_t k = 0; k < n; ++k)
      {
        r.model.push_back(setup.data.points[k].value + fit_sigma[k] * res(k));
        const Eigen::VectorXd row = J.row(k).transpose();
        r.model_standard_deviation.push_back(fit_sigma[k] * std::sqrt(std::max(0.0, row.dot(C * row))));
      }
    std::map<std::pair<int, double>, std::pair<double, double>> series; // (quantity, current) -> T range
    for (const auto &m : setup.data.points)
      {
        const auto key = std::make_pair(int(m.quantity), m.current);
        auto found = series.find(key);
        if (found == series.end())
          series.emplace(key, std::make_pair(m.temperature, m.temperature));
        else
          found->second = {std::min(found->second.first, m.temperature), std::max(found->second.second, m.temperature)};
      }
    for (const auto &[key, range] : series)
      {
        ModelCurve c{MeasuredQuantity(key.first), key.second, {}, {}, {}};
        const int steps = range.second > range.first ? 24 : 0;
        std::vector<Measurement> grid;
        for (int k = 0; k <= steps; ++k)
          {
            const double T = steps ? range.first + (range.second - range.first) * k / steps : range.first;
            c.temperatures.push_back(T);
            grid.push_back({0, T, c.current, c.quantity, 0.0, 0.0});
          }
        const Residuals along(model, setup, grid, std::vector<double>(grid.size(), 1.0), scale, lower, upper);
        Eigen::VectorXd values(grid.size());
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> G(grid.size(), p);
        const double *parameters[] = {x.data()};
        double *jacobians[] = {G.data()};
        if (!along.Evaluate(parameters, values.data(), jacobians))
          throw std::runtime_error("calibrate: the model fails along temperature at the estimate");
        for (std::size_t k = 0; k < grid.size(); ++k)
          {
            c.values.push_back(values(k));
            const Eigen::VectorXd row = G.row(k).transpose();
            c.standard_deviations.push_back(std::sqrt(std::max(0.0, row.dot(C * row))));
          }
        r.curves.push_back(c);
      }
    r.calibrated_overrides = model.overrides(r.estimates);
    return r;
  }
} // namespace servodrift::system
