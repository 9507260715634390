#pragma once
// Field level of the torque motor (model.md 4.1, D10): the planar FEM model of meshes/torque_motor.geo
// at one temperature, with torque by the weighted Maxwell stress tensor and by virtual work.
#include "common/units.h"
#include "common/valve_description.h"
#include "magnetics/magnetostatic_problem.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace servodrift::magnetics
{
  /// Material ids of the torque-motor mesh
  namespace torque_motor_material
  {
    constexpr int armature = 1, pole_pieces = 2, magnet = 3, coil_upper_right = 4, coil_lower_right = 5, air = 6,
                  air_gap = 7, coil_upper_left = 8, coil_lower_left = 9;
  }

  /// The stage's error estimate of a torque (its table's torque_error): the torque minus the torque
  /// on a second mesh of this fraction of the resolution (twice the element size). The stress
  /// tensor is the exact derivative of the discrete coenergy, so virtual work differs from it only
  /// by its difference quotient's error, the same on every mesh; the coarser mesh's change tracks the
  /// discretisation error instead (TorqueMotorField.TheErrorMeshEstimatesTheDiscretisationError...).
  constexpr double error_mesh_resolution_ratio = 0.5;
  /// The residual reduction the error mesh's solves stop at: 1e-8, or `Torque motor/Newton
  /// tolerance' if looser. Its torque then lies within 4e-8 of the largest torque of a solve to
  /// 1e-10 (RV-1's sweep at 40 degC), far inside the change it estimates, and its solves take 0.82 x
  /// the steps.
  inline double error_mesh_tolerance(const ValveDescription &valve)
  {
    return std::max(1e-8, valve.torque_motor.newton_tolerance);
  }
  /// Virtual work's angle step d, [W'(theta + d) - W'(theta - d)]/(2d): the second method, a
  /// verification of the stress tensor (model.md 4.1 item 3) [rad]
  constexpr double virtual_work_step = 0.01 * units::degree;

  struct FieldTorque
  {
    double stress_tensor;      ///< weighted Maxwell stress tensor [N*m]
    double virtual_work;       ///< coenergy difference at constant current [N*m]
    NewtonStatistics newton;   ///< of the solve at the case itself
  };

  class TorqueMotorFieldModel
  {
  public:
    /// Meshes the motor with its dimensions at T (E6-E8, thermal growth of each part) and sets up
    /// the FE problem. `resolution' overrides `Torque motor/Field mesh resolution' if > 0;
    /// `refinements' refines the mesh globally (nested meshes for convergence studies).
    /// `adjust_materials' may change the materials before the problem is set up (verification
    /// studies: linear iron, stronger magnets).
    TorqueMotorFieldModel(const ValveDescription &valve, double temperature, double resolution = 0,
                          unsigned int refinements = 0,
                          const std::function<void(std::map<int, Material> &)> &adjust_materials = {});

    /// Torque at armature angle theta [rad] and differential current i [A]; the previous solves are
    /// the Newton start (MagnetostaticProblem::solve), which stops at `tolerance' (0: `Torque
    /// motor/Newton tolerance'). Virtual work, the second method, only if asked (NaN otherwise).
    FieldTorque torque(double angle, double current, bool virtual_work = false, double tolerance = 0);

    /// Mean |B_y| over the four working gaps of the last solution [T] (C10 calibration measure).
    double mean_gap_flux_density() const;
    /// Largest |B| in the armature of the last solution [T].
    double max_armature_flux_density() const;

    MagnetostaticProblem &problem() { return *fe; }
    unsigned int n_dofs() const { return fe->n_dofs(); }

  private:
    const ValveDescription &valve;
    double temperature;
    std::unique_ptr<MagnetostaticProblem> fe;
  };

  /// The geometry parameters of meshes/torque_motor.geo at temperature T [mm] (the parts were checked
  /// against each other by validate()).
  std::map<std::string, double> torque_motor_geometry_parameters(const ValveDescription &valve, double T,
                                                                 double resolution);
} // namespace servodrift::magnetics
