#include "flow/fv/k_epsilon.h"
#include "flow/fv/wall_distance.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  using namespace k_epsilon;

  namespace
  {
    // Wolfshtein's one-equation model with Chen and Patel's constants near walls, blended into the
    // standard model by Jongen and Marx's function of Re_y
    constexpr double kappa = 0.41;
    const double C_l = kappa * std::pow(C_mu, -0.75); // 2.495
    constexpr double A_mu = 70;                       // length scale of the mu_t damping
    const double A_epsilon = 2 * C_l;                 // gives epsilon -> 2 nu k/y^2 at the wall
    constexpr double Re_y_switch = 60, Re_y_width = 10;
    /// lambda = 1 in the outer (standard k-epsilon) layer, 0 at the wall
    double outer_weight(double Re_y)
    {
      return 0.5 * (1 + std::tanh((Re_y - Re_y_switch) / (Re_y_width / std::atanh(0.98))));
    }
  } // namespace

  KEpsilonTwoLayer::KEpsilonTwoLayer(const FvMesh &mesh, const FluidProperties &fluid,
                                     const BoundaryConditions &boundaries, const FlowSolverParameters &settings,
                                     const MatrixPattern &pattern)
    : KEpsilonModel(mesh, fluid, boundaries, settings, pattern)
    , wall_distance(flow::wall_distance(mesh, boundaries))
    , layer_epsilon(mesh.n_cells(), 0.0)
    , layer_weight(mesh.n_cells(), 0.0)
  {}

  void KEpsilonTwoLayer::wall_terms(const std::vector<Vector2> &, const std::vector<Vector2> &, double k_floor, double)
  {
    const double rho = fluid.density, mu = fluid.viscosity;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const double kc = std::max(k[c], k_floor), y = wall_distance[c];
        const double Re_y = rho * std::sqrt(kc) * y / mu;
        const double l_epsilon = C_l * y * (1 - std::exp(-Re_y / A_epsilon));
        layer_epsilon[c] = std::pow(kc, 1.5) / std::max(l_epsilon, vanishing);
        layer_weight[c] = 1 - outer_weight(Re_y);
        // the rate that sinks k: the wall layer's epsilon where it holds, the transported one outside
        dissipation[c] = layer_weight[c] * layer_epsilon[c] + (1 - layer_weight[c]) * std::max(epsilon[c], 0.0);
      }
  }

  void KEpsilonTwoLayer::constrain_epsilon(FvMatrix &equation)
  {
    // the wall layer: each row becomes (1 - w)(transport) + w a_P (e - e_layer), so that epsilon is
    // the one-equation model's where w = 1 and the transport equation's where w = 0
    const int *inner = equation.A.innerIndexPtr(), *outer = equation.A.outerIndexPtr();
    double *value = equation.A.valuePtr();
    for (std::size_t row = 0; row < mesh.n_cells(); ++row)
      for (int j = outer[row]; j < outer[row + 1]; ++j)
        if (static_cast<std::size_t>(inner[j]) != row)
          value[j] *= 1 - layer_weight[row];
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const double w = layer_weight[c];
        // keeps sum |a_nb| <= a_P (diagonal dominance) for any w
        equation.b[c] = (1 - w) * equation.b[c] + w * equation.diagonal[c] * layer_epsilon[c];
      }
  }

  double KEpsilonTwoLayer::model_viscosity(std::size_t c, double strain) const
  {
    const double rho = fluid.density, mu = fluid.viscosity;
    const double y = wall_distance[c], Re_y = rho * std::sqrt(k[c]) * y / mu;
    const double l_mu = C_l * y * (1 - std::exp(-Re_y / A_mu));
    const double lambda = outer_weight(Re_y);
    return lambda * rho * C_mu * k[c] * realizable_time_scale(k[c] / epsilon[c], strain) +
           (1 - lambda) * rho * C_mu * std::sqrt(k[c]) * l_mu;
  }
} // namespace servodrift::flow
