#pragma once
// The slope limiter of the bounded linear upwind scheme (doc/method.md, "Flow core").
#include "flow/fv/fv_mesh.h"

#include <vector>

namespace servodrift::flow
{
  /// Barth and Jespersen's limiter psi_c in [0, 1] per cell: with the limited gradient psi_c grad_c,
  /// the values reconstructed at the cell's face centres stay within the range of the cell's and its
  /// face neighbours' values (boundary faces: `phi_b'), so that the scheme makes no new extrema.
  std::vector<double> barth_jespersen_limiter(const FvMesh &mesh, const std::vector<double> &phi,
                                              const std::vector<double> &phi_b, const std::vector<Vector2> &grad);
} // namespace servodrift::flow
