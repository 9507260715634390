#pragma once
// The continuity equation's measures, shared by the SIMPLEC correction, the coupled step and the
// post-processing: each cell's mass imbalance and the throughput the continuity residual is
// relative to.
#include "flow/fv/cavitation_model.h"

#include <vector>

namespace servodrift::flow
{
  /// Net mass flux out of each cell, sum over its faces of m F (m the upwind mixture density ratio
  /// where cells cavitate, 1 otherwise) [kg/s per radian]; in a time step (`time', liquid density
  /// `density') a liquid cell's imbalance adds its mass's rate of change, rho V (new_weight -
  /// old_mass)/dt: nonzero where vapour the old levels held has collapsed, which the inflow must
  /// fill (a cavitating cell's mass is its liquid fraction's balance, CavitationModel).
  std::vector<double> cell_mass_imbalance(const FvMesh &mesh, const std::vector<double> &flux,
                                          const CavitationModel &cavitation, const TimeLevel *time = nullptr,
                                          double density = 0);
  /// sum |imbalance| over the cells whose continuity holds: the liquid cells (a cavitating cell's
  /// liquid fraction balances its mass instead).
  double liquid_imbalance_sum(const std::vector<double> &imbalance, const CavitationModel &cavitation);
  /// What the continuity residual is relative to: the velocity inlets' inflow or, in a
  /// pressure-driven flow, the current inflow or outflow of the fluxes F, whichever is larger (from
  /// rest, one of them can pass through nearly zero while the other has built up, and a residual
  /// relative to it would read as a divergence); in a closed domain the mean |F| of a face row.
  double continuity_reference(const FvMesh &mesh, const std::vector<double> &flux, double velocity_inlet_inflow);
} // namespace servodrift::flow
