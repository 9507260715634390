#include "system/calibration_identifiability.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>

namespace servodrift::system
{
  Identifiability identifiability(const Jacobian &J)
  {
    const Eigen::Index p = J.cols();
    Identifiability id;
    id.column_norm = J.colwise().norm().transpose();
    Eigen::MatrixXd unit = J;
    for (Eigen::Index j = 0; j < p; ++j)
      if (id.column_norm(j) > 0)
        unit.col(j) /= id.column_norm(j);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(unit, Eigen::ComputeFullV);
    id.singular_values = svd.singularValues();
    id.directions = svd.matrixV();
    id.identifiable.assign(std::size_t(p), true);
    for (Eigen::Index k = 0; k < id.singular_values.size(); ++k)
      if (!(id.singular_values(k) >= 1e-6 * id.singular_values(0)) || id.singular_values(k) == 0)
        {
          id.lost.push_back(k);
          for (Eigen::Index j = 0; j < p; ++j)
            if (std::abs(id.directions(j, k)) > 0.1)
              id.identifiable[std::size_t(j)] = false;
        }
    for (Eigen::Index k = id.singular_values.size(); k < p; ++k) // fewer values than parameters
      id.lost.push_back(k);
    id.rank = std::size_t(p) - id.lost.size();
    return id;
  }

  std::vector<DeterminedCombination> determined_combinations(const Identifiability &id,
                                                             const std::vector<FreeParameter> &parameters,
                                                             const std::vector<double> &scale,
                                                             const std::vector<double> &estimates, double variance)
  {
    std::vector<Eigen::Index> group; // not identifiable, but acting on the data
    for (std::size_t j = 0; j < parameters.size(); ++j)
      if (!id.identifiable[j] && id.column_norm(Eigen::Index(j)) > 0)
        group.push_back(Eigen::Index(j));
    if (group.empty())
      return {};
    const Eigen::Index g = Eigen::Index(group.size()), p = id.directions.rows();
    Eigen::MatrixXd lost(g, Eigen::Index(id.lost.size()));
    for (Eigen::Index a = 0; a < g; ++a)
      for (Eigen::Index b = 0; b < lost.cols(); ++b)
        lost(a, b) = id.lost[std::size_t(b)] < p ? id.directions(group[std::size_t(a)], id.lost[std::size_t(b)]) : 0.0;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(lost, Eigen::ComputeFullU);
    Eigen::Index lost_rank = 0;
    for (Eigen::Index k = 0; k < svd.singularValues().size(); ++k)
      lost_rank += svd.singularValues()(k) > 1e-8;
    // (J^T J)^+ in unit-column coordinates w_j = |J_j| x_j
    Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(p, p);
    for (Eigen::Index k = 0; k < id.singular_values.size(); ++k)
      if (std::find(id.lost.begin(), id.lost.end(), k) == id.lost.end())
        inverse += id.directions.col(k) * id.directions.col(k).transpose() /
                   (id.singular_values(k) * id.singular_values(k));
    std::vector<DeterminedCombination> combinations;
    for (Eigen::Index c = lost_rank; c < g; ++c)
      {
        // a^T w with a on the group; value_j = start_j + scale_j w_j/|J_j| gives the physical
        // coefficients a_j |J_j|/scale_j, normalised to 1 on the largest of them
        Eigen::VectorXd a = Eigen::VectorXd::Zero(p), physical(g);
        for (Eigen::Index k = 0; k < g; ++k)
          {
            a(group[std::size_t(k)]) = svd.matrixU()(k, c);
            physical(k) = svd.matrixU()(k, c) * id.column_norm(group[std::size_t(k)]) / scale[std::size_t(group[std::size_t(k)])];
          }
        Eigen::Index first = 0;
        physical.cwiseAbs().maxCoeff(&first);
        const double norm = physical(first);
        DeterminedCombination d;
        d.unit = parameters[std::size_t(group[std::size_t(first)])].unit;
        d.estimate = 0;
        for (Eigen::Index k = 0; k < g; ++k)
          {
            const std::size_t j = std::size_t(group[std::size_t(k)]);
            d.paths.push_back(parameters[j].path);
            d.coefficients.push_back(physical(k) / norm);
            d.estimate += d.coefficients.back() * estimates[j];
          }
        a /= norm;
        d.standard_error = std::sqrt(std::max(0.0, variance * a.dot(inverse * a)));
        combinations.push_back(d);
      }
    return combinations;
  }

  std::string DeterminedCombination::text() const
  {
    std::string t;
    for (std::size_t k = 0; k < paths.size(); ++k)
      {
        const double c = coefficients[k];
        t += (k == 0 ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + "));
        if (std::abs(std::abs(c) - 1) > 1e-9)
          t += format_number(std::abs(c)) + " x ";
        t += "`" + paths[k] + "'";
      }
    return t;
  }
} // namespace servodrift::system
