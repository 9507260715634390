#pragma once
// The fields the units of the flow solver share (simplec.h): the cell velocities and pressure, the
// face fluxes, the boundary face values and the pressure gradient. Each unit reads and writes them
// by these names; the turbulence and cavitation models keep their own fields.
#include "flow/fv/fv_mesh.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
  struct FluidProperties
  {
    double density;   ///< rho [kg/m^3]
    double viscosity; ///< dynamic viscosity mu [Pa*s]
  };

  /// The scaled residuals of one outer iteration.
  struct Residuals
  {
    double u = 0, v = 0;       ///< scaled momentum residuals
    double continuity = 0;     ///< sum of cell mass imbalances / throughput
    double k = 0, epsilon = 0; ///< scaled residuals of the turbulence equations (0 if laminar)
  };
  /// The largest of them.
  inline double largest_residual(const Residuals &r) { return std::max({r.u, r.v, r.continuity, r.k, r.epsilon}); }
  /// Which of them is the largest: 0 u, 1 v, 2 continuity, 3 k, 4 epsilon (the turbulence model's
  /// second equation, epsilon or omega); residual_names names them.
  inline unsigned int largest_residual_index(const Residuals &r)
  {
    const double all[] = {r.u, r.v, r.continuity, r.k, r.epsilon};
    unsigned int largest = 0;
    for (unsigned int i = 1; i < 5; ++i)
      if (all[i] > all[largest])
        largest = i;
    return largest;
  }
  inline constexpr const char *residual_names[] = {"u", "v", "continuity", "k", "epsilon"};

  /// The solution fields, for continuation: what a solver can start from.
  struct FlowFields
  {
    std::vector<double> u, v, p, flux, k, epsilon, turbulent_viscosity;
    std::vector<double> face_area;                 ///< of the mesh they were computed on
    double density = 0;                            ///< of the fluid they were computed with
    std::vector<std::pair<std::string, double>> boundary_pressures; ///< pressure patches
    bool turbulent = false;
    std::vector<double> liquid_fraction; ///< with cavitation (empty otherwise)
    std::vector<char> cavitating;
  };

  /// The fields of one time level: cell velocities [m/s], the mixture density over the liquid's [1]
  /// and the face fluxes F (FlowState::flux).
  struct TimeLevelFields
  {
    std::vector<double> u, v, mixture, flux;
    /// the turbulence model's transported fields (TurbulenceModel::transported_fields)
    std::vector<std::vector<double>> turbulence;
  };

  /// The time derivative of SimplecSolver::advance, second-order backward differences (BDF2; the
  /// first step after a start, or after dt changed, implicit Euler): dphi/dt at the new level is
  /// (new_weight phi - sum of the old levels' weighted phi)/dt; a cavitating cell's mass balance
  /// takes the same of the mixture ratio m.
  struct TimeLevel
  {
    double dt = 0;            ///< [s]; 0: steady
    TimeLevelFields last;     ///< level n
    TimeLevelFields before;   ///< level n - 1 (empty: implicit Euler)
    /// BDF2: 3/2, 2, -1/2; implicit Euler: 1, 1, 0
    double new_weight() const { return before.u.empty() ? 1.0 : 1.5; }
    double last_weight() const { return before.u.empty() ? 1.0 : 2.0; }
    double before_weight() const { return before.u.empty() ? 0.0 : -0.5; }
    /// sum over the old levels of weight x m x (phi: 1 for the mass balance)
    double old_mass(std::size_t c) const
    {
      return last_weight() * last.mixture[c] + (before.u.empty() ? 0.0 : before_weight() * before.mixture[c]);
    }
    /// sum over the old levels of weight x velocity component
    double old_velocity(int component, std::size_t c) const
    {
      double sum = last_weight() * (component == 0 ? last.u : last.v)[c];
      if (!before.u.empty())
        sum += before_weight() * (component == 0 ? before.u : before.v)[c];
      return sum;
    }
    /// sum over the old levels of weight x the turbulence model's transported field `field'
    double old_turbulence(std::size_t field, std::size_t c) const
    {
      double sum = last_weight() * last.turbulence[field][c];
      if (!before.u.empty())
        sum += before_weight() * before.turbulence[field][c];
      return sum;
    }
    /// rho_m V/dt of each cell in the current iteration (the momentum equations' and the turbulence
    /// model's time terms) [kg/s]
    std::vector<double> storage_rate;
  };

  /// The solver's own state at one iteration.
  struct FlowState
  {
    explicit FlowState(const FvMesh &mesh)
      : u(mesh.n_cells(), 0.0)
      , v(mesh.n_cells(), 0.0)
      , p(mesh.n_cells(), 0.0)
      , flux(mesh.n_faces(), 0.0)
      , u_b(mesh.n_faces(), 0.0)
      , v_b(mesh.n_faces(), 0.0)
      , p_b(mesh.n_faces(), 0.0)
      , grad_p(mesh.n_cells(), Vector2::Zero())
    {}

    std::vector<double> u, v; ///< cell velocity (x axial, y radial) [m/s]
    std::vector<double> p;    ///< cell pressure [Pa]
    /// F = rho u.S through each face, out of its owner, at the liquid's density rho [kg/s, per radian
    /// if axisymmetric]: the face flux of the discrete continuity and momentum equations. Where cells
    /// cavitate, the mass that crosses a face is the mixture's (CavitationModel::mixture_flux).
    std::vector<double> flux;
    std::vector<double> u_b, v_b, p_b; ///< values at the boundary faces (indexed by face; interior entries unused)
    std::vector<Vector2> grad_p;       ///< least-squares pressure gradient per cell [Pa/m]
  };
} // namespace servodrift::flow
