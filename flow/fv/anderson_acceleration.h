#pragma once
// Anderson acceleration of a fixed-point iteration x <- G(x) (Anderson 1965; Walker and Ni 2011,
// "type II" with mixing 1): the next iterate is G's latest value corrected by the differences of its
// last m values, with the weights that make the combined change f = G(x) - x smallest in the least-
// squares sense. For a linear contraction this is GMRES in disguise; for SIMPLEC it removes the slow,
// nearly linear tail of the iteration. The fixed point is the same: only the path to it changes.
#include <Eigen/Dense>

#include <deque>

namespace servodrift::flow
{
  class AndersonAcceleration
  {
  public:
    explicit AndersonAcceleration(unsigned int depth);

    /// x: the iterate G was applied to; g = G(x). Returns the next iterate (g itself until there
    /// is a history).
    Eigen::VectorXd next(const Eigen::VectorXd &x, const Eigen::VectorXd &g);
    /// Forgets the history (after a change of the map, or a step that went wrong).
    void restart();
    /// |f| = |G(x) - x| of the last call.
    double change_norm() const { return last_change_norm; }
    std::size_t history_size() const { return change_differences.size(); }

  private:
    unsigned int depth;
    std::deque<Eigen::VectorXd> change_differences; ///< f_k - f_(k-1)
    std::deque<Eigen::VectorXd> value_differences;  ///< g_k - g_(k-1)
    Eigen::MatrixXd gram; ///< (f_i - f_(i-1)) . (f_j - f_(j-1)) of the history, updated a column at a time
    Eigen::VectorXd previous_change, previous_value;
    bool has_previous = false;
    double last_change_norm = 0;
  };
} // namespace servodrift::flow
