#pragma once
// SimplecSolver's implementation: the units of the flow solver and the state they share. Private to
// simplec.cc (the outer iteration and the queries) and simplec_state.cc (continuation and the state
// that Anderson acceleration combines).
#include "flow/fv/cavitation_model.h"
#include "flow/fv/coupled_step.h"
#include "flow/fv/iteration_control.h"
#include "flow/fv/momentum_equation.h"
#include "flow/fv/pressure_equation.h"
#include "flow/fv/simplec.h"
#include "flow/fv/turbulence_model.h"

#include <memory>
#include <string>
#include <vector>

namespace servodrift::flow
{
  struct SimplecSolver::Implementation : public AcceleratedState
  {
    Implementation(const FvMesh &mesh, const FluidProperties &fluid,
                   const std::map<std::string, BoundaryCondition> &boundaries, const FlowSolverParameters &settings);

    /// One outer iteration, SIMPLEC or coupled as the control says (with the time term while a time
    /// step is on, `previous'); its scaled residuals.
    Residuals iterate(const IterationControl &control);
    /// The end of a solve or a time step: the boundary values and the pressure gradient of the final
    /// fields, and the report.
    SolveReport finish(const IterationControl &control, const Residuals &r);
    /// The momentum equations' implicit Euler term of the current mixture and the last time level.
    const MomentumEquation::TimeTerm &update_time_term();
    /// The boundary face values of the state (walls' pressure at least the vapour pressure).
    void update_boundary_values() { boundaries.update_values(state, cavitation.pressure_floor()); }
    /// The mass that crosses each face: the mixture's with cavitation.
    const std::vector<double> &mass_flux() const { return cavitation.convecting_flux(state.flux); }
    /// The progress report of an iteration on stderr (`Report interval').
    void report_progress(const IterationControl &control, const Residuals &r) const;

    // AcceleratedState: u, v, p, F, the turbulence model's fields and the liquid fraction
    Eigen::VectorXd pack() override;
    void unpack(const Eigen::VectorXd &x) override;
    void forget_scales() override { field_scales.clear(); }
    std::vector<std::vector<double> *> accelerated_fields();

    const FvMesh &mesh;
    FluidProperties fluid;
    FlowSolverParameters settings;
    BoundaryConditions boundaries;
    FlowState state;
    MatrixPattern pattern;
    MomentumEquation momentum;
    PressureEquation pressure;
    CoupledStep coupled;
    CavitationModel cavitation;
    std::unique_ptr<TurbulenceModel> turbulence;
    ConvergenceMonitor monitor;
    TimeLevel previous;                   ///< the old time levels while SimplecSolver::advance runs (dt 0: steady)
    double time_step = 0;                 ///< of the last step (BDF2 needs the same dt)
    /// A change of the state other than a time step: the next step starts with implicit Euler.
    void forget_time_levels() { previous = {}, time_step = 0; }
    MomentumEquation::TimeTerm time_term; ///< of `previous' and the current mixture
    std::vector<double> field_scales; ///< of the accelerated fields (empty: set at the next pack)
  };
} // namespace servodrift::flow
