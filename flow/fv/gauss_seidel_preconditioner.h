#pragma once
// Symmetric Gauss-Seidel preconditioner for Eigen's iterative solvers (BiCGSTAB): M = (D + L) D^-1
// (D + U), applied as a forward and a backward sweep over the cells. The transport matrices of
// flow/fv/simplec (momentum, k, epsilon) are upwind convection-diffusion matrices: a sweep carries
// information along the flow through the whole domain where a Jacobi step moves it one cell, so
// BiCGSTAB needs a quarter of the iterations for the same reduction (`Flow solver/Momentum solver',
// doc/performance.md).
//
// Works on a compressed row-major matrix with every diagonal entry stored (the finite-volume
// transport matrices, flow/fv/fv_matrix.h), row by row: the forward sweep solves (D + L) w = r with the
// entries left of each row's diagonal, the backward sweep (D + U) z = D w with those right of it.
// Each row waits for the one before it, so a division there would set the sweep's pace: the
// inverse diagonal is formed once in compute() (a sweep then costs about as much as a product A x).
// No other set-up than that and locating the diagonal.
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
    /// outlive the solve, its values current) and finds each row's diagonal entry.
    template <typename MatrixType>
    SymmetricGaussSeidelPreconditioner &compute(const MatrixType &A)
    {
      static_assert(MatrixType::Flags & Eigen::RowMajorBit, "a row-major matrix");
      n = A.rows();
      outer = A.outerIndexPtr(), inner = A.innerIndexPtr(), value = A.valuePtr();
      ok = A.isCompressed();
      diagonal.assign(std::size_t(n), -1);
      for (Eigen::Index c = 0; ok && c < n; ++c)
        {
          // the column indices of a compressed row are sorted
          const int *d = std::lower_bound(inner + outer[c], inner + outer[c + 1], int(c));
          ok = d != inner + outer[c + 1] && *d == c && value[d - inner] != 0;
          diagonal[std::size_t(c)] = int(d - inner);
        }
      inverse.resize(std::size_t(n));
      for (Eigen::Index c = 0; ok && c < n; ++c)
        inverse[std::size_t(c)] = 1 / value[diagonal[std::size_t(c)]];
      return *this;
    }

    Eigen::ComputationInfo info() const { return ok ? Eigen::Success : Eigen::NumericalIssue; }

    /// z = M^-1 r.
    template <typename Rhs>
    Eigen::VectorXd solve(const Eigen::MatrixBase<Rhs> &r) const
    {
      Eigen::VectorXd z(n);
      // forward: (D + L) w = r, row i with the w_j, j < i, already found
      for (Eigen::Index i = 0; i < n; ++i)
        {
          const int d = diagonal[std::size_t(i)];
          double sum = r[i];
          for (int k = outer[i]; k < d; ++k)
            sum -= value[k] * z[inner[k]];
          z[i] = sum * inverse[std::size_t(i)];
        }
      // backward: (D + U) z = D w, row i with the z_j, j > i, already found
      for (Eigen::Index i = n; i-- > 0;)
        {
          const int d = diagonal[std::size_t(i)];
          double sum = value[d] * z[i];
          for (int k = d + 1; k < outer[i + 1]; ++k)
            sum -= value[k] * z[inner[k]];
          z[i] = sum * inverse[std::size_t(i)];
        }
      return z;
    }

  private:
    Eigen::Index n = 0;
    const int *outer = nullptr, *inner = nullptr;
    const double *value = nullptr;
    std::vector<double> inverse; ///< 1 / a_ii of each row
    std::vector<int> diagonal; ///< index of each row's diagonal entry in the value array
    bool ok = false;
  };
} // namespace servodrift::flow
