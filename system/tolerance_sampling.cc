#include "system/tolerance_sampling.h"

#include "common/error.h"

#include <boost/math/distributions/binomial.hpp>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/CorrelationMatrix.hxx>
#include <openturns/JansenSensitivityAlgorithm.hxx>
#include <openturns/LHSExperiment.hxx>
#include <openturns/LowDiscrepancyExperiment.hxx>
#include <openturns/MartinezSensitivityAlgorithm.hxx>
#include <openturns/MauntzKucherenkoSensitivityAlgorithm.hxx>
#include <openturns/Normal.hxx>
#include <openturns/NormalCopula.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/SaltelliSensitivityAlgorithm.hxx>
#include <openturns/SobolIndicesAlgorithm.hxx>
#include <openturns/SobolIndicesExperiment.hxx>
#include <openturns/SobolSequence.hxx>
#include <openturns/TBB.hxx>
#include <openturns/TruncatedNormal.hxx>
#include <openturns/Uniform.hxx>

#include <algorithm>

namespace servodrift::system
{
  namespace
  {
    /// The joint distribution of the active quantities: the marginals of `Tolerances', tied by a
    /// Gaussian copula when correlations are given (validate_tolerances checked the matrix).
    OT::Distribution joint_distribution(const ToleranceParameters &t)
    {
      // OpenTURNS' own threads would share the cores with the MPI ranks; results do not depend on them.
      OT::TBB::SetThreadsNumber(1);
      const auto active = t.active();
      OT::Collection<OT::Distribution> marginals;
      for (const std::size_t q : active)
        {
          const ToleranceDistribution &d = t.distributions[q];
          switch (d.kind)
            {
              case ToleranceDistribution::Kind::normal:
                marginals.add(OT::Normal(d.mean, d.standard_deviation));
                break;
              case ToleranceDistribution::Kind::truncated_normal:
                marginals.add(OT::TruncatedNormal(d.mean, d.standard_deviation, d.lower, d.upper));
                break;
              case ToleranceDistribution::Kind::uniform:
                marginals.add(OT::Uniform(d.lower, d.upper));
                break;
              case ToleranceDistribution::Kind::none: break;
            }
        }
      if (t.correlations.empty())
        return OT::ComposedDistribution(marginals);
      OT::CorrelationMatrix R(active.size());
      for (const auto &c : t.correlations)
        {
          const std::size_t i = std::find(active.begin(), active.end(), c.first) - active.begin();
          const std::size_t j = std::find(active.begin(), active.end(), c.second) - active.begin();
          R(i, j) = c.coefficient;
        }
      return OT::ComposedDistribution(marginals, OT::NormalCopula(R));
    }

    SampleRows rows_of(const OT::Sample &s)
    {
      SampleRows rows(s.getSize(), std::vector<double>(s.getDimension()));
      for (OT::UnsignedInteger i = 0; i < s.getSize(); ++i)
        for (OT::UnsignedInteger j = 0; j < s.getDimension(); ++j)
          rows[i][j] = s(i, j);
      return rows;
    }

    OT::Sample sample_of(const SampleRows &rows)
    {
      OT::Sample s(rows.size(), rows.empty() ? 0 : rows.front().size());
      for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t j = 0; j < rows[i].size(); ++j)
          s(i, j) = rows[i][j];
      return s;
    }

    /// OpenTURNS reports a bad argument with its own exception; ours name the entry to change.
    template <class F>
    auto guarded(const char *what, F &&f)
    {
      try
        {
          return f();
        }
      catch (const OT::Exception &e)
        {
          throw InputError(std::string(what) + ": " + std::string(e.what()).substr(0, 200) +
                           " (check the distributions in subsection `Tolerances')");
        }
    }
  } // namespace

  SampleRows draw_valves(const ToleranceParameters &t)
  {
    return guarded("drawing the valves", [&] {
      const OT::Distribution joint = joint_distribution(t);
      OT::RandomGenerator::SetSeed(t.seed);
      switch (t.sampling)
        {
          case ToleranceParameters::Sampling::latin_hypercube:
            if (!t.correlations.empty())
              throw InputError("`Tolerances/Sampling' = latin-hypercube needs independent quantities (allowed "
                               "with `Tolerances/Correlations': monte-carlo, randomised-sobol-sequence)");
            return rows_of(OT::LHSExperiment(joint, t.samples, false, true).generate());
          case ToleranceParameters::Sampling::randomised_sobol_sequence:
            {
              OT::LowDiscrepancyExperiment e(OT::SobolSequence(joint.getDimension()), joint, t.samples, true);
              e.setRandomize(true);
              return rows_of(e.generate());
            }
          case ToleranceParameters::Sampling::monte_carlo: break;
        }
      return rows_of(joint.getSample(t.samples));
    });
  }

  SampleRows sobol_design(const ToleranceParameters &t)
  {
    return guarded("the Sobol' design", [&] {
      const OT::Distribution joint = joint_distribution(t);
      OT::RandomGenerator::SetSeed(t.seed + 1); // independent of the Monte Carlo valves
      return rows_of(OT::SobolIndicesExperiment(joint, t.sobol_base_samples, false).generate());
    });
  }

  SobolIndices sobol_indices(const ToleranceParameters &t, const SampleRows &design, const std::vector<double> &output,
                             double floor)
  {
    // An output that no tolerance moves (the null shift at the nulling temperature; or only the
    // magnets' remanence toleranced, which leaves an otherwise ideal valve's null where it is) has
    // no variance to share out: estimators given round-off return noise, not indices.
    const std::size_t unevaluated = std::size_t(
      std::count_if(output.begin(), output.end(), [](double y) { return !std::isfinite(y); }));
    double mean = 0, variance = 0;
    for (double y : output)
      mean += y / double(output.size());
    for (double y : output)
      variance += (y - mean) * (y - mean) / double(std::max<std::size_t>(output.size(), 2) - 1);
    const double spread = std::sqrt(variance);
    if (unevaluated > 0 || !(spread > floor))
      {
        const std::size_t d = design.empty() ? 0 : design.front().size();
        SobolIndices none;
        none.first_order.assign(d, 0.0);
        none.total.assign(d, 0.0);
        none.first_order_interval.assign(d, {0.0, 0.0});
        none.total_interval.assign(d, {0.0, 0.0});
        none.undefined = unevaluated > 0 ? std::to_string(unevaluated) + " of the design's " +
                                             std::to_string(output.size()) +
                                             " valves have no value (outside the tables): the design is incomplete"
                         : spread == 0 ? "the output does not vary over the design"
                                     : "the output's standard deviation over the design, " + format_number(spread) +
                                         ", is at most its floor " + format_number(floor) +
                                         " (round-off, not a tolerance's effect)";
        return none;
      }
    return guarded("the Sobol' indices", [&] {
      const OT::Sample X = sample_of(design);
      OT::Sample Y(output.size(), 1);
      for (std::size_t i = 0; i < output.size(); ++i)
        Y(i, 0) = output[i];
      const OT::UnsignedInteger N = t.sobol_base_samples;
      OT::SobolIndicesAlgorithm algorithm;
      switch (t.sobol_estimator)
        {
          case ToleranceParameters::SobolEstimator::saltelli:
            algorithm = OT::SaltelliSensitivityAlgorithm(X, Y, N);
            break;
          case ToleranceParameters::SobolEstimator::jansen: algorithm = OT::JansenSensitivityAlgorithm(X, Y, N); break;
          case ToleranceParameters::SobolEstimator::martinez:
            algorithm = OT::MartinezSensitivityAlgorithm(X, Y, N);
            break;
          case ToleranceParameters::SobolEstimator::mauntz_kucherenko:
            algorithm = OT::MauntzKucherenkoSensitivityAlgorithm(X, Y, N);
            break;
        }
      algorithm.setBootstrapSize(t.bootstrap_size);
      algorithm.setConfidenceLevel(t.confidence_level);
      OT::RandomGenerator::SetSeed(t.seed + 2); // the bootstrap's resamples
      SobolIndices r;
      const OT::Point S = algorithm.getFirstOrderIndices(), ST = algorithm.getTotalOrderIndices();
      const OT::Interval IS = algorithm.getFirstOrderIndicesInterval(), IT = algorithm.getTotalOrderIndicesInterval();
      for (OT::UnsignedInteger k = 0; k < S.getDimension(); ++k)
        {
          r.first_order.push_back(S[k]);
          r.total.push_back(ST[k]);
          r.first_order_interval.push_back({IS.getLowerBound()[k], IS.getUpperBound()[k]});
          r.total_interval.push_back({IT.getLowerBound()[k], IT.getUpperBound()[k]});
        }
      return r;
    });
  }

  std::vector<double> quantiles(const std::vector<double> &values, const std::vector<double> &p)
  {
    OT::Sample s(values.size(), 1);
    for (std::size_t i = 0; i < values.size(); ++i)
      s(i, 0) = values[i];
    std::vector<double> q;
    for (double probability : p)
      q.push_back(s.computeQuantilePerComponent(probability)[0]);
    return q;
  }

  Interval proportion_interval(std::size_t successes, std::size_t trials, double level)
  {
    using boost::math::binomial_distribution;
    const double alpha = (1 - level) / 2;
    const auto n = double(trials), k = double(successes);
    return {binomial_distribution<>::find_lower_bound_on_p(n, k, alpha),
            binomial_distribution<>::find_upper_bound_on_p(n, k, alpha)};
  }
} // namespace servodrift::system
