#include "flow/fv/turbulence_model.h"

#include "flow/fv/k_epsilon.h"
#include "flow/fv/k_omega_sst.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  std::unique_ptr<TurbulenceModel> TurbulenceModel::create(const FvMesh &mesh, const FluidProperties &fluid,
                                                           const BoundaryConditions &boundaries,
                                                           const FlowSolverParameters &settings,
                                                           const MatrixPattern &pattern)
  {
    switch (settings.turbulence)
      {
        case FlowSolverParameters::Turbulence::k_epsilon:
          return std::make_unique<KEpsilonTwoLayer>(mesh, fluid, boundaries, settings, pattern);
        case FlowSolverParameters::Turbulence::k_epsilon_launder_sharma:
          return std::make_unique<KEpsilonLaunderSharma>(mesh, fluid, boundaries, settings, pattern);
        case FlowSolverParameters::Turbulence::k_omega_sst:
          return std::make_unique<KOmegaSST>(mesh, fluid, boundaries, settings, pattern);
        default: return std::make_unique<LaminarFlow>(mesh, fluid, boundaries);
      }
  }

  TurbulenceModel::TurbulenceModel(const FvMesh &mesh_, const FluidProperties &fluid_,
                                   const BoundaryConditions &boundaries_)
    : mesh(mesh_)
    , fluid(fluid_)
    , boundaries(boundaries_)
    , mu_t(mesh_.n_cells(), 0.0)
    , mu_face(mesh_.n_faces(), fluid_.viscosity)
  {}

  void TurbulenceModel::set_viscosity_limit(double ratio)
  {
    viscosity_ratio_limit = ratio;
    const double limit = ratio * fluid.viscosity;
    for (double &value : mu_t)
      value = std::min(value, limit);
    update_face_viscosity();
  }

  void TurbulenceModel::add_time_term(FvMatrix &equation, const TimeLevel &time, std::size_t field)
  {
    for (std::size_t c = 0; c < equation.diagonal.size(); ++c)
      {
        equation.diagonal[c] += time.storage_rate[c] * time.new_weight();
        equation.b[c] += time.storage_rate[c] * time.old_turbulence(field, c);
      }
  }

  void TurbulenceModel::update_face_viscosity()
  {
    mesh.for_each_face([&](std::size_t f, unsigned int, unsigned int) { mu_face[f] = fluid.viscosity + mesh.interpolate(f, mu_t); },
                       [&](std::size_t f, unsigned int P) {
                         const double mut = boundaries.kind(f) != BoundaryCondition::Kind::wall ? mu_t[P] : 0.0;
                         mu_face[f] = fluid.viscosity + mut;
                       });
  }

  void TurbulenceModel::scale_two_equation_fields(double s, std::vector<double> &k, std::vector<double> &k_b,
                                                  std::vector<double> &second, std::vector<double> &second_b,
                                                  double second_factor)
  {
    auto scale = [](std::vector<double> &x, double factor) {
      for (double &value : x)
        value *= factor;
    };
    scale(mu_t, std::sqrt(s));
    scale(k, s), scale(k_b, s);
    scale(second, second_factor), scale(second_b, second_factor);
    update_face_viscosity();
  }

  void TurbulenceModel::bound_two_equation_fields(std::vector<double> &k, std::vector<double> &second,
                                                  const std::vector<std::vector<double>> &before)
  {
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        k[c] = std::max(k[c], two_equation::accelerated_decrease * before[0][c]);
        second[c] = std::max(second[c], two_equation::accelerated_decrease * before[1][c]);
        mu_t[c] = std::max(mu_t[c], 0.0);
      }
    update_face_viscosity();
  }

  LaminarFlow::LaminarFlow(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries)
    : TurbulenceModel(mesh, fluid, boundaries)
  {
    update_face_viscosity();
  }
} // namespace servodrift::flow
