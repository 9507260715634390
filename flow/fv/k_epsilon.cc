#include "flow/fv/k_epsilon.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace servodrift::flow
{
  using namespace k_epsilon;
  using namespace two_equation;

  KEpsilonModel::KEpsilonModel(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries,
                               const FlowSolverParameters &settings_, const MatrixPattern &pattern)
    : TurbulenceModel(mesh, fluid, boundaries)
    , settings(settings_)
    , k(mesh.n_cells(), 0.0)
    , epsilon(mesh.n_cells(), 0.0)
    , k_b(mesh.n_faces(), 0.0)
    , epsilon_b(mesh.n_faces(), 0.0)
    , dissipation(mesh.n_cells(), 0.0)
    , k_sink(mesh.n_cells(), 0.0)
    , epsilon_source(mesh.n_cells(), 0.0)
    , destruction_factor(mesh.n_cells(), 1.0)
    , k_equation(mesh, pattern)
    , epsilon_equation(mesh, pattern)
  {
    update_face_viscosity();
  }

  TurbulenceResiduals KEpsilonModel::correct(const FlowState &s, const std::vector<double> &convecting_flux,
                                             const TimeLevel *time)
  {
    using Kind = BoundaryCondition::Kind;
    const std::size_t n = mesh.n_cells(), nf = mesh.n_faces();
    const double rho = fluid.density, mu = fluid.viscosity, alpha = settings.turbulence_relaxation;
    const bool axisymmetric = mesh.geometry == Geometry::axisymmetric;
    TurbulenceResiduals r;

    // boundary values
    double k_inflow = 0, epsilon_inflow = 0;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      const BoundaryCondition &bc = boundaries.of_face(f);
      if (boundaries.kind(f) == Kind::wall)
        k_b[f] = 0, epsilon_b[f] = wall_epsilon(P);
      else if (s.flux[f] < 0 && (boundaries.kind(f) == Kind::velocity_inlet || boundaries.is_pressure_boundary(f)))
        {
          const double u_n = -s.flux[f] / (rho * mesh.face_area[f]);
          if (bc.turbulence_profile)
            std::tie(k_b[f], epsilon_b[f]) = bc.turbulence_profile(mesh.face_center[f]);
          else
            {
              k_b[f] = 1.5 * std::pow(bc.turbulence_intensity * u_n, 2);
              epsilon_b[f] = std::pow(C_mu, 0.75) * std::pow(k_b[f], 1.5) / bc.turbulence_length;
            }
          k_inflow = std::max(k_inflow, k_b[f]), epsilon_inflow = std::max(epsilon_inflow, epsilon_b[f]);
        }
      else
        k_b[f] = k[P], epsilon_b[f] = epsilon[P];
    });
    // A start from nothing (or from a laminar solution): turbulence of 5 % intensity of the local
    // flow speed, at least the inflow's, with the inflow's length scale. Low-Reynolds and two-layer
    // models have a laminar branch (k = 0 solves them), so a seed as weak as a slow plenum's inflow
    // would never grow where the real flow is turbulent; a strong seed decays where it is not.
    if (*std::max_element(k.begin(), k.end()) <= 0)
      {
        const double L = boundaries.of_patch(0).turbulence_length;
        double k_start_max = 0, epsilon_start_max = 0;
        for (std::size_t c = 0; c < n; ++c)
          {
            k[c] = std::max(k_inflow, 1.5 * std::pow(seed_intensity * std::hypot(s.u[c], s.v[c]), 2));
            epsilon[c] = std::max(epsilon_inflow, std::pow(C_mu, 0.75) * std::pow(k[c], 1.5) / L);
            k_start_max = std::max(k_start_max, k[c]), epsilon_start_max = std::max(epsilon_start_max, epsilon[c]);
          }
        if (k_inflow <= 0)
          k_inflow = k_start_max, epsilon_inflow = epsilon_start_max;
      }
    const double k_floor = floor_fraction * std::max(k_inflow, *std::max_element(k.begin(), k.end()));
    const double epsilon_floor = floor_fraction * std::max(epsilon_inflow, *std::max_element(epsilon.begin(), epsilon.end()));

    // velocity gradients, production P = mu_t G and the strain rate |S| = sqrt(S_ij S_ij)
    const std::vector<Vector2> gu = mesh.gradient(s.u, s.u_b), gv = mesh.gradient(s.v, s.v_b);
    std::vector<double> production(n), strain(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        double G = 2 * (gu[c].x() * gu[c].x() + gv[c].y() * gv[c].y()) + std::pow(gu[c].y() + gv[c].x(), 2);
        if (axisymmetric)
          G += 2 * std::pow(s.v[c] / mesh.cell_center[c].y(), 2);
        production[c] = mu_t[c] * G;
        strain[c] = std::sqrt(0.5 * G);
      }
    wall_terms(gu, gv, k_floor, epsilon_floor);

    // face diffusivities mu + mu_t/sigma
    std::vector<double> gamma(nf);
    auto diffusivity = [&](double sigma) {
      for (std::size_t f = 0; f < nf; ++f)
        gamma[f] = mu + (mu_face[f] - mu) / sigma;
    };
    double scale = 0;
    // residuals relative to the level of k and e the inflow brings (or the largest), not to the
    // local values: where turbulence decays towards laminar flow, those vanish and a relative
    // residual would never fall
    const double k_level = std::max(k_inflow, level_fraction * *std::max_element(k.begin(), k.end()));
    const double epsilon_level = std::max(epsilon_inflow, level_fraction * *std::max_element(epsilon.begin(), epsilon.end()));
    std::vector<double> level(n);

    // k: the dissipation rho e (+ D) as an implicit sink rho e/k k. D is linearised at the k of the
    // cell, but in a hole (a cell whose k has fallen below hole_fraction of its neighbours' mean: the
    // bounded linear upwind correction took it below the floor) at that mean: D = 2 mu |grad sqrt k|^2
    // stays finite as the hole's k goes to 0, so D/k would grow without bound and hold the hole there,
    // a state the equations (D itself as the sink) do not have. A solution without holes is unchanged.
    diffusivity(sigma_k);
    k_equation.assemble_convection_diffusion(k, k_b, gamma, convecting_flux, boundaries, settings.convection);
    const std::vector<double> k_around = std::any_of(k_sink.begin(), k_sink.end(), [](double D) { return D > 0; })
                                           ? neighbour_mean(k)
                                           : std::vector<double>(n, 0.0);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c], kc = std::max(k[c], k_floor);
        const double k_sink_linearised_at = kc < hole_fraction * k_around[c] ? k_around[c] : kc;
        k_equation.diagonal[c] += (rho * dissipation[c] / kc + k_sink[c] / k_sink_linearised_at) * V;
        k_equation.b[c] += production[c] * V;
      }
    if (time)
      add_time_term(k_equation, *time, 0);
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(k[c], k_level);
    r.k = k_equation.relax(k, alpha, level, scale);
    r.k /= std::max(scale, vanishing);
    // the state the k equation is linearised at (the iteration's start): a variant that takes the
    // epsilon equation's terms from it keeps its k and the production of its own mu_t there
    const double mu_t_limit = viscosity_ratio_limit * mu;
    const bool from_linearised_state = epsilon_terms_from_linearised_state();
    const std::vector<double> k_linearised = from_linearised_state ? k : std::vector<double>{};
    std::vector<double> epsilon_production = production;
    if (from_linearised_state)
      for (std::size_t c = 0; c < n; ++c)
        epsilon_production[c] = k[c] > 0 && epsilon[c] > 0
                                  ? std::min(model_viscosity(c, strain[c]), mu_t_limit) * 2 * strain[c] * strain[c]
                                  : 0;
    k_equation.solve(k, settings, settings.turbulence_solver, "k");

    // epsilon: C1 e/k P [+ E] as the source, C2 [f_2] rho e^2/k as an implicit sink
    diffusivity(sigma_epsilon);
    epsilon_equation.assemble_convection_diffusion(epsilon, epsilon_b, gamma, convecting_flux, boundaries,
                                                   settings.convection);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c];
        const double kc = std::max(from_linearised_state ? k_linearised[c] : k[c], k_floor);
        const double ratio = std::max(epsilon[c], 0.0) / kc;
        epsilon_equation.diagonal[c] += C2 * destruction_factor[c] * rho * ratio * V;
        epsilon_equation.b[c] += (C1 * ratio * epsilon_production[c] + epsilon_source[c]) * V;
      }
    if (time)
      add_time_term(epsilon_equation, *time, 1);
    constrain_epsilon(epsilon_equation);
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(epsilon[c], epsilon_level);
    r.epsilon = epsilon_equation.relax(epsilon, alpha, level, scale);
    r.epsilon /= std::max(scale, vanishing);
    epsilon_equation.solve(epsilon, settings, settings.turbulence_solver, "epsilon");

    // bounded, then the turbulent viscosity (relaxed, at most the limit)
    cells_at_limit = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        k[c] = std::max(k[c], k_floor);
        epsilon[c] = std::max(epsilon[c], epsilon_floor);
        const double target = model_viscosity(c, strain[c]);
        cells_at_limit += target > mu_t_limit;
        mu_t[c] += settings.turbulent_viscosity_relaxation * (std::min(target, mu_t_limit) - mu_t[c]);
      }
    update_face_viscosity();
    return r;
  }

  std::vector<double> KEpsilonModel::neighbour_mean(const std::vector<double> &phi) const
  {
    std::vector<double> sum(phi.size(), 0.0), count(phi.size(), 0.0);
    mesh.for_each_interior_face([&](std::size_t, unsigned int P, unsigned int N) {
      sum[P] += phi[N], count[P] += 1;
      sum[N] += phi[P], count[N] += 1;
    });
    for (std::size_t c = 0; c < phi.size(); ++c)
      sum[c] /= std::max(count[c], 1.0);
    return sum;
  }

  double KEpsilonModel::realizable_time_scale(double time_scale, double strain) const
  {
    // Durbin (1996): mu_t <= a rho k/(sqrt 6 |S|) keeps the normal stresses of the Boussinesq form
    // >= 0 where the strain is strong (the orifice's entry, the jet's stagnation on the flapper),
    // which the models violate: there their production, and with it mu_t, runs away. A log layer's
    // k/e = 1/(sqrt(2 C_mu) |S|) (|S| = sqrt(S_ij S_ij)) stays 13 % below the bound at a = 0.6.
    if (settings.realizability_coefficient <= 0)
      return time_scale;
    return std::min(time_scale,
                    settings.realizability_coefficient / (std::sqrt(6.0) * C_mu * std::max(strain, vanishing)));
  }

  void KEpsilonModel::store(FlowFields &f) const
  {
    f.turbulent = true;
    f.k = k, f.epsilon = epsilon, f.turbulent_viscosity = mu_t;
  }

  void KEpsilonModel::restore(const FlowFields &o)
  {
    if (o.turbulent)
      k = o.k, epsilon = o.epsilon, mu_t = o.turbulent_viscosity;
    else // from laminar fields: the model seeds itself at its next step
      std::fill(k.begin(), k.end(), 0.0), std::fill(epsilon.begin(), epsilon.end(), 0.0),
        std::fill(mu_t.begin(), mu_t.end(), 0.0);
    update_face_viscosity();
  }

  void KEpsilonModel::scale_pressure_level(double s)
  {
    scale_two_equation_fields(s, k, k_b, epsilon, epsilon_b, s * std::sqrt(s));
  }

  std::vector<std::vector<double>> KEpsilonModel::transported_fields() const { return {k, epsilon}; }

  std::vector<std::vector<double> *> KEpsilonModel::accelerated_fields() { return {&k, &epsilon, &mu_t}; }

  void KEpsilonModel::bound_accelerated(const std::vector<std::vector<double>> &before)
  {
    bound_two_equation_fields(k, epsilon, before);
  }

  std::vector<std::pair<std::string, const std::vector<double> *>> KEpsilonModel::output_fields() const
  {
    return {{"k", &k}, {"epsilon", &epsilon}, {"turbulent_viscosity", &mu_t}};
  }
} // namespace servodrift::flow
