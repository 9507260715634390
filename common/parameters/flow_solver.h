#pragma once
#include <string>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Flow solver": numerics of the finite-volume solver (flow/, issue 4).
  struct FlowSolverParameters
  {
    static constexpr const char *subsection = "Flow solver";
    enum class Convection { upwind, bounded_linear_upwind };
    Convection convection;          ///< face values of the convected velocity
    double velocity_relaxation;     ///< alpha_u of the momentum equations [1]
    double pressure_relaxation;     ///< alpha_p of the pressure correction (1 for SIMPLEC) [1]
    enum class Coupling { simplec, coupled, simplec_then_coupled };
    Coupling coupling;              ///< pressure-velocity coupling: SIMPLEC, one coupled system, or SIMPLEC until it stalls
    enum class MomentumSolver { bicgstab_jacobi, bicgstab_gauss_seidel, bicgstab_ilu, direct };
    MomentumSolver momentum_solver; ///< linear solver of the momentum equations
    MomentumSolver turbulence_solver; ///< linear solver of k, epsilon and omega (BiCGSTAB's preconditioners only)
    double linear_solver_tolerance; ///< BiCGSTAB's residual reduction of momentum, k, epsilon, omega [1]
    double tolerance;               ///< scaled residuals of momentum and continuity [1]
    unsigned int max_iterations;    ///< SIMPLEC iterations before the run fails
    unsigned int stall_window;      ///< iterations per window of the stall test (0: off)
    unsigned int cycle_window;      ///< iterations per window of the cycle test that lowers alpha_p (0: off)
    unsigned int report_interval;   ///< print the residuals every n iterations (0: never)
    unsigned int monitor_iterations; ///< window over which monitored quantities must settle [1]
    double monitor_tolerance;       ///< their largest relative change over that window [1]
    enum class Turbulence { laminar, k_epsilon, k_epsilon_launder_sharma, k_omega_sst };
    Turbulence turbulence;          ///< laminar; standard k-epsilon, two-layer; Launder-Sharma k-epsilon; k-omega SST
    double turbulence_relaxation;   ///< under-relaxation of the k and epsilon equations [1]
    double turbulent_viscosity_relaxation; ///< under-relaxation of mu_t [1]
    double vapour_density_ratio;    ///< cavitation: vapour over liquid density in the mixture [1]
    double realizability_coefficient; ///< Durbin's time-scale bound alpha (two-layer k-epsilon; 0: off) [1]
    unsigned int acceleration_depth;  ///< Anderson acceleration: iterates kept (0: plain SIMPLEC) [1]
    double acceleration_start;        ///< Anderson acceleration: from this largest scaled residual down [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
