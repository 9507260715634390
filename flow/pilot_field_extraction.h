#pragma once
// The extraction of a field-level pilot case's results (model.md 4.2), for flow/pilot_field.cc.
#include "flow/pilot_field.h"
#include "flow/simplec.h"

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

  /// What the solver's fields give at pressure difference dp, with the outlet's absolute pressure
  /// `downstream' [Pa]: Q from the outlet; C_d on the bore area (orifice, Re by E17) or the curtain
  /// pi D_N h (nozzle, Re by E18); the flapper's and the land's pressure forces, the bore exit's
  /// mean pressure and axial momentum; the lowest absolute pressure, whether the case cavitates,
  /// the largest wall y+ and mu_t/mu. The iteration counts are the caller's.
  PilotFieldResult extract_pilot_result(const SimplecSolver &solver, const FvMesh &mesh, const PilotCaseShape &shape,
                                        const PilotFieldCase &conditions, double vapour_pressure,
                                        double downstream, double dp);
} // namespace servodrift::flow
