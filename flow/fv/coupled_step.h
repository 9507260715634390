#pragma once
// One coupled pressure-velocity iteration (`Flow solver/Pressure-velocity coupling = coupled', and
// where SIMPLEC stalls): the relaxed momentum equations and continuity of the Rhie-Chow fluxes as one
// linear system in (u, v, p), solved by UMFPACK LU (doc/method.md, "Coupled pressure-velocity
// iterations"):
//   momentum:   A u + V G_int(p) = b + V G_int(p_old)   (G_int: the least-squares gradient's
//               interior part; its boundary part, with the walls' extrapolated pressure, stays
//               explicit in b, so that at convergence the equation is SIMPLEC's exactly)
//   continuity: sum_f m_f F_f = 0,  F_f = rho u_f . S - c_f ((p_N - p_P) - mean(grad p)_f . d)
//               with u_f = w u_P + (1 - w) u_N implicit, the mean gradient of the last pressure
//               explicit, c_f the face's pressure coefficient (rhie_chow.h) and m_f the upwind
//               mixture density ratio of the last fluxes.
// Cavitating cells hold p = p_cav in place of their continuity (their liquid fraction balances
// their mass, as with SIMPLEC).
#include "flow/fv/cavitation_model.h"
#include "flow/fv/momentum_equation.h"

#include <memory>
#include <vector>

namespace servodrift::flow
{
  class CoupledStep
  {
  public:
    CoupledStep(const FvMesh &mesh, double density);
    ~CoupledStep();

    /// Solves for the state's u, v and p (the pressure update relaxed by `relaxation': 1 unless a
    /// cycle was caught) and its fluxes; returns the liquid cells' mass imbalance of the state it
    /// started from (its Rhie-Chow fluxes), and in `throughput' what that is relative to
    /// (continuity_reference).
    double solve(FlowState &state, const MomentumEquation &momentum, const BoundaryConditions &boundaries,
                 CavitationModel &cavitation, double relaxation, double &throughput);

  private:
    const FvMesh &mesh;
    double density;
    struct System;
    std::unique_ptr<System> system;
  };
} // namespace servodrift::flow
