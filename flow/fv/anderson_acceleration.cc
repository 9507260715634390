#include "flow/fv/anderson_acceleration.h"

#include <stdexcept>

namespace servodrift::flow
{
  AndersonAcceleration::AndersonAcceleration(unsigned int depth_)
    : depth(depth_)
  {
    if (depth == 0)
      throw std::invalid_argument("Anderson acceleration needs a depth of at least 1");
  }

  void AndersonAcceleration::restart()
  {
    change_differences.clear();
    value_differences.clear();
    gram.resize(0, 0);
    has_previous = false;
  }

  Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd &x, const Eigen::VectorXd &g)
  {
    Eigen::VectorXd f = g - x;
    last_change_norm = f.norm();
    if (has_previous)
      {
        if (change_differences.size() == depth)
          {
            change_differences.pop_front(), value_differences.pop_front();
            const Eigen::Index kept = Eigen::Index(depth) - 1;
            gram.topLeftCorner(kept, kept) = gram.bottomRightCorner(kept, kept).eval();
          }
        change_differences.push_back(f - previous_change);
        value_differences.push_back(g - previous_value);
        const Eigen::Index last = Eigen::Index(change_differences.size()) - 1;
        if (gram.rows() < Eigen::Index(depth))
          gram.conservativeResize(Eigen::Index(depth), Eigen::Index(depth));
        for (Eigen::Index j = 0; j <= last; ++j)
          gram(j, last) = gram(last, j) = change_differences[std::size_t(j)].dot(change_differences.back());
      }
    previous_change = f;
    previous_value = g;
    has_previous = true;
    const Eigen::Index m = Eigen::Index(change_differences.size());
    if (m == 0)
      return g;
    // gamma = argmin |f - dF gamma| by the normal equations dF^T dF gamma = dF^T f: the Gram matrix
    // costs one column of dot products per call (a QR of the tall dF would cost m times more, as much
    // as a third of a SIMPLEC iteration). Nearly dependent columns (an iteration that has almost
    // converged in some direction) are kept from amplifying by the pseudo-inverse of the Gram
    // matrix's eigen-decomposition, which drops directions below 1e-12 of the largest eigenvalue.
    Eigen::VectorXd rhs(m);
    for (Eigen::Index j = 0; j < m; ++j)
      rhs[j] = change_differences[std::size_t(j)].dot(f);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram.topLeftCorner(m, m));
    const Eigen::VectorXd lambda = eigen.eigenvalues();
    const double largest = lambda.cwiseAbs().maxCoeff();
    Eigen::VectorXd projected = eigen.eigenvectors().transpose() * rhs;
    for (Eigen::Index j = 0; j < m; ++j)
      projected[j] = lambda[j] > 1e-12 * largest ? projected[j] / lambda[j] : 0.0;
    const Eigen::VectorXd gamma = eigen.eigenvectors() * projected;
    Eigen::VectorXd next = g;
    for (Eigen::Index j = 0; j < m; ++j)
      next -= gamma[j] * value_differences[std::size_t(j)];
    return next;
  }
} // namespace servodrift::flow
