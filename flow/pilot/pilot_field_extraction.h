#pragma once
// The extraction of a field-level pilot case's results (model.md 4.2), for flow/pilot_field.cc.
#include "flow/pilot/pilot_field.h"
#include "flow/fv/simplec.h"

#include <vector>

namespace servodrift::flow
{
  /// sqrt(2 dp / rho): the ideal (Bernoulli) velocity of a pressure difference [m/s].
  double ideal_velocity(double dp, double rho);

  /// The dimensions a case's results are extracted with.
  struct PilotCaseShape
  {
    PilotGeometry kind;
    double gap;         ///< nozzle-flapper gap h [m]
    double bore_radius; ///< r_0 (orifice) or D_N/2 (nozzle) [m]
    const std::vector<unsigned int> &exit_faces; ///< nozzle: interior faces of the bore's exit section
  };

  /// Where a case's Q (and its C_d, and the nozzle's Re) is metered. In a steady state the inlet and
  /// the outlet pass the same flow but for the cavitating cells' imbalance, which the steady
  /// convergence test leaves out (doc/method.md, "Mass balance with cavitation"); in a time step they
  /// differ by the rate the mixture's mass in the domain changes at, which a cavity downstream of the
  /// restriction carries to the outlet only: the inlet's is the flow the restriction draws, choked
  /// and steady where the cavity is not.
  enum class MeteredAt
  {
    outlet, ///< a steady state: the flow its convergence monitor follows
    inlet   ///< a time step (PilotField::advance)
  };

  /// What the solver's fields give at pressure difference dp, with the outlet's absolute pressure
  /// `downstream' [Pa]: Q through the patch `metered'; C_d on the bore area (orifice, Re by E17) or the curtain
  /// pi D_N h (nozzle, Re by E18); the flapper's and the land's pressure forces, the bore exit's
  /// mean pressure and axial momentum; the lowest absolute pressure, whether the case cavitates,
  /// the largest wall y+ and mu_t/mu. The iteration counts are the caller's.
  PilotFieldResult extract_pilot_result(const SimplecSolver &solver, const FvMesh &mesh, const PilotCaseShape &shape,
                                        const PilotFieldCase &conditions, double vapour_pressure,
                                        double downstream, double dp, MeteredAt metered);
} // namespace servodrift::flow
