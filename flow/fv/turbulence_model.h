#pragma once
// Turbulence models of the flow solver behind one interface (doc/method.md, "Turbulence"), as
// OpenFOAM's momentumTransportModel: the momentum equations read the effective viscosity mu + mu_t
// of each face and mu_t of each cell; after each outer iteration the model takes one step of its own
// equations with the new velocities and fluxes. A new model is one class derived from this one
// (k_epsilon.h shows the shape) and one line in TurbulenceModel::create.
#include "common/parameters/flow_solver.h"
#include "flow/fv/boundary_conditions.h"
#include "flow/fv/fv_matrix.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
  /// The numerical settings the two-equation models (k_epsilon.h, k_omega_sst.h) share.
  namespace two_equation
  {
    /// A start from nothing: turbulence of this intensity of the local flow speed
    constexpr double seed_intensity = 0.05;
    /// k and the second field are kept above this fraction of their inflow's (or largest) value
    constexpr double floor_fraction = 1e-12;
    /// the residuals are relative to at least this fraction of the largest value
    constexpr double level_fraction = 1e-6;
    /// a combination of Anderson acceleration may lower k and the second field at most tenfold
    constexpr double accelerated_decrease = 0.1;
  } // namespace two_equation

  /// The scaled residuals of a model's two transport equations (0 if it has none).
  struct TurbulenceResiduals
  {
    double k = 0, epsilon = 0;
  };

  class TurbulenceModel
  {
  public:
    /// The model `settings.turbulence' names.
    static std::unique_ptr<TurbulenceModel> create(const FvMesh &mesh, const FluidProperties &fluid,
                                                   const BoundaryConditions &boundaries,
                                                   const FlowSolverParameters &settings, const MatrixPattern &pattern);
    TurbulenceModel(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries);
    virtual ~TurbulenceModel() = default;

    virtual bool turbulent() const = 0;
    /// One step of the model's equations with the velocities and fluxes of this iteration (F the
    /// convecting mass flux), then the new mu_t and face viscosities; the scaled residuals. With
    /// `time' (SimplecSolver::advance), each transported field phi's equation holds rho_m dphi/dt.
    virtual TurbulenceResiduals correct(const FlowState &state, const std::vector<double> &convecting_flux,
                                        const TimeLevel *time = nullptr) = 0;
    /// The fields the model transports (k and epsilon or omega; none if laminar), for the old time
    /// levels of a time step.
    virtual std::vector<std::vector<double>> transported_fields() const = 0;

    /// mu_t per cell [Pa*s] (zeros if laminar).
    const std::vector<double> &viscosity() const { return mu_t; }
    /// mu + mu_t per face, the molecular mu at walls (mu_t vanishes there with k) [Pa*s].
    const std::vector<double> &face_viscosity() const { return mu_face; }

    /// The largest mu_t as a multiple of mu (1e5 unless set; applies to the current field at once,
    /// so that the next iteration's residuals see it). The model's mu_t is held at the limit where it
    /// would exceed it; cells_at_viscosity_limit() counts them in the last step.
    void set_viscosity_limit(double ratio);
    std::size_t cells_at_viscosity_limit() const { return cells_at_limit; }

    /// Continuation: the model's fields into / from FlowFields (from laminar fields a model seeds
    /// itself at its next step); scaling to another pressure level by s (velocities by sqrt(s)).
    virtual void store(FlowFields &fields) const = 0;
    virtual void restore(const FlowFields &fields) = 0;
    virtual void scale_pressure_level(double s) = 0;
    /// The fields Anderson acceleration combines, and their bounds after a combination (`before':
    /// copies of the same fields before it).
    virtual std::vector<std::vector<double> *> accelerated_fields() = 0;
    virtual void bound_accelerated(const std::vector<std::vector<double>> &before) = 0;
    /// Cell fields written to the VTU output, by name.
    virtual std::vector<std::pair<std::string, const std::vector<double> *>> output_fields() const = 0;

  protected:
    /// The time term of transported field number `field' (transported_fields' order) in its
    /// equation, advective as the momentum equations' (momentum_equation.h): rho_m V/dt (new_weight
    /// phi - the old levels' weighted phi), the first part on the diagonal, the rest in b.
    static void add_time_term(FvMatrix &equation, const TimeLevel &time, std::size_t field);
    /// mu_face from mu_t: linear interpolation inside, the cell's at inflows, outflows, the axis and
    /// symmetry planes, none at walls.
    void update_face_viscosity();
    /// scale_pressure_level of a two-equation model: k (cells and boundary faces) by s, its second
    /// field by second_factor (epsilon ~ U^3/L: s^(3/2); omega ~ U/L: s^(1/2)), mu_t by sqrt(s).
    void scale_two_equation_fields(double s, std::vector<double> &k, std::vector<double> &k_b,
                                   std::vector<double> &second, std::vector<double> &second_b, double second_factor);
    /// bound_accelerated of a two-equation model: a combination may overshoot below zero where k or
    /// the second field is small; each keeps at least the positive value it came from, scaled down at
    /// most tenfold (two_equation::accelerated_decrease); mu_t stays non-negative.
    void bound_two_equation_fields(std::vector<double> &k, std::vector<double> &second,
                                   const std::vector<std::vector<double>> &before);

    const FvMesh &mesh;
    FluidProperties fluid;
    const BoundaryConditions &boundaries;
    std::vector<double> mu_t, mu_face;
    double viscosity_ratio_limit = 1e5;
    std::size_t cells_at_limit = 0;
  };

  /// No model: mu_t = 0.
  class LaminarFlow : public TurbulenceModel
  {
  public:
    LaminarFlow(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries);
    bool turbulent() const override { return false; }
    TurbulenceResiduals correct(const FlowState &, const std::vector<double> &, const TimeLevel *) override { return {}; }
    std::vector<std::vector<double>> transported_fields() const override { return {}; }
    void store(FlowFields &fields) const override { fields.turbulent = false; }
    void restore(const FlowFields &) override {}
    void scale_pressure_level(double) override {}
    std::vector<std::vector<double> *> accelerated_fields() override { return {}; }
    void bound_accelerated(const std::vector<std::vector<double>> &) override {}
    std::vector<std::pair<std::string, const std::vector<double> *>> output_fields() const override { return {}; }
  };
} // namespace servodrift::flow
