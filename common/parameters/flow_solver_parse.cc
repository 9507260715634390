#include "common/parameters/flow_solver.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void FlowSolverParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    convection = prm.get("Convection scheme") == "upwind" ? Convection::upwind : Convection::bounded_linear_upwind;
    velocity_relaxation = prm.get_double("Velocity relaxation");
    pressure_relaxation = prm.get_double("Pressure relaxation");
    const std::string coupling_name = prm.get("Pressure-velocity coupling");
    coupling = coupling_name == "coupled"              ? Coupling::coupled :
               coupling_name == "simplec-then-coupled" ? Coupling::simplec_then_coupled :
                                                         Coupling::simplec;
    // one reading of the solver names for both entries (`Turbulence solver' offers no "direct")
    auto linear_solver = [&prm](const char *entry) {
      const std::string m = prm.get(entry);
      return m == "direct"                ? MomentumSolver::direct :
             m == "bicgstab-ilu"          ? MomentumSolver::bicgstab_ilu :
             m == "bicgstab-gauss-seidel" ? MomentumSolver::bicgstab_gauss_seidel :
                                            MomentumSolver::bicgstab_jacobi;
    };
    momentum_solver = linear_solver("Momentum solver");
    turbulence_solver = linear_solver("Turbulence solver");
    linear_solver_tolerance = prm.get_double("Linear solver tolerance");
    tolerance = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    stall_window = prm.get_integer("Stall window");
    cycle_window = prm.get_integer("Cycle window");
    report_interval = prm.get_integer("Report interval");
    monitor_iterations = prm.get_integer("Monitor iterations");
    monitor_tolerance = prm.get_double("Monitor tolerance");
    const std::string t = prm.get("Turbulence model");
    turbulence = t == "k-epsilon"                 ? Turbulence::k_epsilon :
                 t == "k-epsilon-launder-sharma" ? Turbulence::k_epsilon_launder_sharma :
                 t == "k-omega-sst"              ? Turbulence::k_omega_sst :
                                                   Turbulence::laminar;
    turbulence_relaxation = prm.get_double("Turbulence relaxation");
    turbulent_viscosity_relaxation = prm.get_double("Turbulent viscosity relaxation");
    realizability_coefficient = prm.get_double("Realizability coefficient");
    vapour_density_ratio = prm.get_double("Vapour density ratio");
    acceleration_depth = prm.get_integer("Acceleration depth");
    acceleration_start = prm.get_double("Acceleration start");
    prm.leave_subsection();
  }
} // namespace servodrift
