#pragma once
// Symmetric Gauss-Seidel preconditioner for Eigen's iterative solvers (BiCGSTAB): M = (D + L) D^-1
// (D + U), applied as a forward and a backward sweep over the cells. The transport matrices of
// flow/simplec (momentum, k, epsilon) are upwind convection-diffusion matrices: a sweep carries
// information along the flow through the whole domain where a Jacobi step moves it one cell, so
// BiCGSTAB needs a quarter of the iterations for the same reduction; but the sweeps cost more than
// the iterations they save on the valve's meshes (`Flow solver/Momentum solver', doc/performance.md).
//
// Works on a compressed column-major matrix with every diagonal entry stored (the
// finite-volume matrices), column by column: the forward sweep solves (D + L) w = r eliminating
// with the entries below the diagonal of each column, the backward sweep (D + U) z = D w with those
// above it. No set-up beyond locating the diagonal (compute()).
#include <Eigen/Sparse>

#include <algorithm>
#include <vector>

namespace servodrift::flow
{
  class SymmetricGaussSeidelPreconditioner
  {
  public:
    SymmetricGaussSeidelPreconditioner() = default;
    template <typename MatrixType>
    explicit SymmetricGaussSeidelPreconditioner(const MatrixType &A)
    {
      compute(A);
    }

    template <typename MatrixType>
    SymmetricGaussSeidelPreconditioner &analyzePattern(const MatrixType &)
    {
      return *this;
    }
    template <typename MatrixType>
    SymmetricGaussSeidelPreconditioner &factorize(const MatrixType &A)
    {
      return compute(A);
    }
    /// Takes A's compressed arrays (A is the solver's own matrix or a reference to it and must
    /// outlive the solve, its values current) and finds each column's diagonal entry.
    template <typename MatrixType>
    SymmetricGaussSeidelPreconditioner &compute(const MatrixType &A)
    {
      static_assert(!(MatrixType::Flags & Eigen::RowMajorBit), "a column-major matrix");
      n = A.cols();
      outer = A.outerIndexPtr(), inner = A.innerIndexPtr(), value = A.valuePtr();
      ok = A.isCompressed();
      diagonal.assign(std::size_t(n), -1);
      for (Eigen::Index c = 0; ok && c < n; ++c)
        {
          // the row indices of a compressed column are sorted
          const int *d = std::lower_bound(inner + outer[c], inner + outer[c + 1], int(c));
          ok = d != inner + outer[c + 1] && *d == c && value[d - inner] != 0;
          diagonal[std::size_t(c)] = int(d - inner);
        }
      return *this;
    }

    Eigen::ComputationInfo info() const { return ok ? Eigen::Success : Eigen::NumericalIssue; }

    /// z = M^-1 r.
    template <typename Rhs>
    Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs> &r) const
    {
      Eigen::VectorXd z = r;
      // forward: (D + L) w = r; column c's entries below the diagonal eliminate w_c from later rows
      for (Eigen::Index c = 0; c < n; ++c)
        {
          const int d = diagonal[std::size_t(c)];
          const double w = z[c] / value[d];
          z[c] = w;
          for (int k = d + 1; k < outer[c + 1]; ++k)
            z[inner[k]] -= value[k] * w;
        }
      // backward: (D + U) z = D w; column c's entries above the diagonal eliminate z_c from earlier rows
      for (Eigen::Index c = 0; c < n; ++c)
        z[c] *= value[diagonal[std::size_t(c)]];
      for (Eigen::Index c = n; c-- > 0;)
        {
          const int d = diagonal[std::size_t(c)];
          const double zc = z[c] / value[d];
          z[c] = zc;
          for (int k = outer[c]; k < d; ++k)
            z[inner[k]] -= value[k] * zc;
        }
      return z;
    }

  private:
    Eigen::Index n = 0;
    const int *outer = nullptr, *inner = nullptr;
    const double *value = nullptr;
    std::vector<int> diagonal; ///< index of each column's diagonal entry in the value array
    bool ok = false;
  };
} // namespace servodrift::flow
