#pragma once
// What the flow solver reports of its fields (SimplecSolver's queries): flow rates, mean pressures
// and pressure forces on patches, the wall y+ of the first cells, the mass balance of the converged
// fields (the VTU output is vtu_writer.h). A full revolution if axisymmetric, unit depth if planar.
#include "flow/fv/boundary_conditions.h"
#include "flow/fv/cavitation_model.h"

#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
  /// The faces of a patch; std::invalid_argument if the mesh has none of that name.
  const std::vector<unsigned int> &patch_faces(const FvMesh &mesh, const std::string &patch);
  /// Per radian (axisymmetric) or per unit depth (planar) -> the whole device: 2 pi or 1.
  double revolution(const FvMesh &mesh);

  /// Volume flow out through a patch, the mass flux over the liquid density [m^3/s].
  double flow_rate(const FvMesh &mesh, const std::vector<double> &mass_flux, double density, const std::string &patch);
  /// Area-weighted mean of the boundary pressure on a patch [Pa].
  double mean_pressure(const FvMesh &mesh, const std::vector<double> &p_b, const std::string &patch);
  /// Mass-flux-weighted mean total pressure p + rho |u|^2/2 through a patch (the mean pressure if
  /// nothing flows) [Pa].
  double mean_total_pressure(const FvMesh &mesh, const FlowState &state, const std::vector<double> &mass_flux,
                             double density, const std::string &patch);
  /// The lowest cell or boundary-face pressure [Pa].
  double minimum_pressure(const FvMesh &mesh, const FlowState &state);
  /// Integral of (p - p_reference) n . e over a patch, n out of the fluid: the pressure force of the
  /// fluid on the wall along e [N].
  double pressure_force(const FvMesh &mesh, const std::vector<double> &p_b, const std::string &patch,
                        const Vector2 &direction, double p_reference);
  /// y+ of the first cell centre at a wall, rho u_tau d/mu with the wall shear mu |u_t|/d of the
  /// resolved sublayer, per cell (the largest over its wall faces; 0 away from walls) [1].
  std::vector<double> wall_y_plus(const FvMesh &mesh, const FlowState &state, const BoundaryConditions &boundaries,
                                  const FluidProperties &fluid);

  /// The mass inflow through the boundary [kg/s per radian or unit depth].
  double throughput(const FvMesh &mesh, const std::vector<double> &mass_flux);
  /// The largest |net mass flux| of a cell (the mixture's where cells cavitate), relative to the
  /// throughput [1].
  double max_cell_imbalance(const FvMesh &mesh, const std::vector<double> &flux, const CavitationModel &cavitation);
  /// |net mass flux out of the domain| relative to the throughput [1].
  double net_imbalance(const FvMesh &mesh, const std::vector<double> &mass_flux);
} // namespace servodrift::flow
