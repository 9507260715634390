#pragma once
// Turbulence models of the flow solver behind one interface (doc/method.md, "Turbulence"), as
// OpenFOAM's momentumTransportModel: the momentum equations read the effective viscosity mu + mu_t
// of each face and mu_t of each cell; after each outer iteration the model takes one step of its own
// equations with the new velocities and fluxes. A new model is one class derived from this one
// (k_epsilon.h shows the shape) and one line in TurbulenceModel::create.
#include "common/parameters/flow_solver.h"
#include "flow/boundary_conditions.h"
#include "flow/fv_matrix.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
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
    /// convecting mass flux), then the new mu_t and face viscosities; the scaled residuals.
    virtual TurbulenceResiduals correct(const FlowState &state, const std::vector<double> &convecting_flux) = 0;

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
    /// mu_face from mu_t: linear interpolation inside, the cell's at inflows, outflows, the axis and
    /// symmetry planes, none at walls.
    void update_face_viscosity();

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
    TurbulenceResiduals correct(const FlowState &, const std::vector<double> &) override { return {}; }
    void store(FlowFields &fields) const override { fields.turbulent = false; }
    void restore(const FlowFields &) override {}
    void scale_pressure_level(double) override {}
    std::vector<std::vector<double> *> accelerated_fields() override { return {}; }
    void bound_accelerated(const std::vector<std::vector<double>> &) override {}
    std::vector<std::pair<std::string, const std::vector<double> *>> output_fields() const override { return {}; }
  };
} // namespace servodrift::flow
