#pragma once
// Rhie and Chow's face fluxes of collocated velocity and pressure (doc/method.md, "Flow core"):
//   F_f = rho [u_f . S - D_f ((p_N - p_P) - mean(grad p)_f . d) |S|/(n . d)],
// u_f and D_f linearly interpolated, D = V/a_P of the momentum equations: the compact pressure
// difference minus the interpolated gradient along d removes the checkerboard of collocated grids
// and vanishes for a linear pressure. Its pressure term, a D_f |S|/(n . d), is the one face
// coefficient of the pressure-velocity coupling: with a = rho it is c_f, the change of F per unit
// change of p_N - p_P, which the SIMPLEC correction (with D~) and the coupled step share.
#include "flow/fv/boundary_conditions.h"

#include <vector>

namespace servodrift::flow
{
  /// a D_f |S|/(n . d) of face f: interior faces with the interpolated D, boundary faces with the
  /// owner's D and its normal distance to the face. a = rho: the face's pressure coefficient c_f
  /// [kg/(s Pa) per radian]; a = a pressure difference: the pressure part of rho^-1 F_f.
  inline double face_coefficient(const FvMesh &mesh, std::size_t f, const std::vector<double> &D, double a)
  {
    if (mesh.neighbour[f] >= 0)
      return a * mesh.interpolate(f, D) * mesh.face_area[f] / mesh.normal_distance(f);
    return a * D[mesh.owner[f]] * mesh.face_area[f] / mesh.distance_to_face(f);
  }

  /// The Rhie-Chow fluxes of the state's velocities and pressures with the momentum coefficients D:
  /// interior faces as above; pressure boundaries the same one-sided, with the boundary pressure;
  /// velocity inlets keep the fluxes of `state'; walls, the axis and symmetry planes carry none.
  std::vector<double> rhie_chow_fluxes(const FvMesh &mesh, double density, const FlowState &state,
                                       const std::vector<double> &D, const BoundaryConditions &boundaries);

  /// With a time step (SimplecSolver::advance), the face's share of the old levels' momentum (Choi,
  /// AIAA J. 37 (1999) 1155): F_f += (rho m D/dt)_f sum_k w_k (F_k,f - rho u_k,f . S), the old
  /// flux less its interpolated velocity's, w_k the weights of the time levels (flow_state.h), m the
  /// current mixture density ratio (the momentum equations' time term's). Without it the
  /// interpolation would see the old levels' momentum only through the cell velocities and a flow
  /// marched to rest would depend on dt; with it (and alpha_u = 1 in a step) it is the steady
  /// solution. rho m D/dt is interpolated as one cell value.
  /// Interior faces and pressure boundaries (one-sided, the owner's D and velocity).
  void add_time_step_correction(const FvMesh &mesh, double density, const TimeLevel &time, const std::vector<double> &D,
                                const std::vector<double> &mixture, const BoundaryConditions &boundaries,
                                std::vector<double> &F);
} // namespace servodrift::flow
