#pragma once
// Grid sequencing (issue 5): the fields of a solution on one mesh carried to another mesh of the
// same domain (a coarser or finer resolution of the same template), as the starting state of a
// solve there. Not conservative and not meant to be: SIMPLEC rebuilds the fluxes from the carried
// velocities (SimplecSolver::set_fields) and converges from there.
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"

namespace servodrift::flow
{
  /// Each cell value of `to' is the inverse-distance weighted mean of the values of the cells of
  /// `from' whose centres are nearest to its centre (a convex combination: k, epsilon, mu_t stay
  /// >= 0 and the liquid fraction in [0, 1]). A cell cavitates where its nearest source cell does.
  /// The face fluxes are left empty (set_fields computes them on the new mesh); the boundary
  /// pressures, the density and the model flags are kept.
  FlowFields transfer_fields(const FvMesh &from, const FlowFields &fields, const FvMesh &to);
} // namespace servodrift::flow
