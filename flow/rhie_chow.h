#pragma once
// Rhie and Chow's face fluxes of collocated velocity and pressure (doc/method.md, "Flow core"):
//   F_f = rho [u_f . S - D_f ((p_N - p_P) - mean(grad p)_f . d) |S|/(n . d)],
// u_f and D_f linearly interpolated, D = V/a_P of the momentum equations: the compact pressure
// difference minus the interpolated gradient along d removes the checkerboard of collocated grids
// and vanishes for a linear pressure. c_f = rho D_f |S|/(n . d) is the face's pressure coefficient:
// the flux's change per unit change of p_N - p_P, which the SIMPLEC correction and the coupled step
// share.
#include "flow/boundary_conditions.h"

#include <vector>

namespace servodrift::flow
{
  /// c_f = rho D_f |S|/(n . d) of face f: interior faces with the interpolated D, boundary faces with
  /// the owner's D and its normal distance to the face [kg/(s Pa) per radian].
  inline double pressure_face_coefficient(const FvMesh &mesh, std::size_t f, double density,
                                          const std::vector<double> &D)
  {
    if (mesh.neighbour[f] >= 0)
      return density * mesh.interpolate(f, D) * mesh.face_area[f] / mesh.normal_distance(f);
    return density * D[mesh.owner[f]] * mesh.face_area[f] / mesh.distance_to_face(f);
  }

  /// The Rhie-Chow fluxes of the state's velocities and pressures with the momentum coefficients D:
  /// interior faces as above; pressure boundaries the same one-sided, with the boundary pressure;
  /// velocity inlets keep the fluxes of `state'; walls, the axis and symmetry planes carry none.
  std::vector<double> rhie_chow_fluxes(const FvMesh &mesh, double density, const FlowState &state,
                                       const std::vector<double> &D, const BoundaryConditions &boundaries);
} // namespace servodrift::flow
