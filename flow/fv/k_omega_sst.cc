#include "flow/fv/k_omega_sst.h"

#include "flow/fv/wall_distance.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  using namespace two_equation;

  namespace
  {
    // Menter, Kuntz and Langtry (2003): the inner (k-omega) and the outer (k-epsilon) sets
    constexpr double beta_star = 0.09, a1 = 0.31;
    constexpr double alpha_1 = 5.0 / 9, beta_1 = 0.075, sigma_k1 = 0.85, sigma_omega1 = 0.5;
    constexpr double alpha_2 = 0.44, beta_2 = 0.0828, sigma_k2 = 1.0, sigma_omega2 = 0.856;
    /// P~ = min(P, this beta* rho k omega): the production limiter
    constexpr double production_limit = 10;
    /// the floor of the cross-diffusion CD_kw in F1's argument (the reference's 1e-10, SI)
    constexpr double cross_diffusion_floor = 1e-10;
    /// the wall's omega, this times the sublayer's 6 nu/(beta_1 d^2) (Menter 1994)
    constexpr double wall_omega_factor = 10;

    double blend(double F1, double inner, double outer) { return F1 * inner + (1 - F1) * outer; }
  } // namespace

  KOmegaSST::KOmegaSST(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries,
                       const FlowSolverParameters &settings_, const MatrixPattern &pattern)
    : TurbulenceModel(mesh, fluid, boundaries)
    , settings(settings_)
    , wall_distance(flow::wall_distance(mesh, boundaries))
    , k(mesh.n_cells(), 0.0)
    , omega(mesh.n_cells(), 0.0)
    , k_b(mesh.n_faces(), 0.0)
    , omega_b(mesh.n_faces(), 0.0)
    , F1(mesh.n_cells(), 1.0)
    , F2(mesh.n_cells(), 1.0)
    , k_equation(mesh, pattern)
    , omega_equation(mesh, pattern)
  {
    std::vector<double> nearest(mesh.n_cells(), 0.0);
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      if (boundaries.kind(f) != BoundaryCondition::Kind::wall)
        return;
      const double d = mesh.distance_to_face(f);
      nearest[P] = nearest[P] > 0 ? std::min(nearest[P], d) : d;
    });
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      if (nearest[c] > 0)
        wall_cells.emplace_back(static_cast<unsigned int>(c), nearest[c]);
    update_face_viscosity();
  }

  void KOmegaSST::boundary_values(const FlowState &s, double &k_inflow, double &omega_inflow)
  {
    using Kind = BoundaryCondition::Kind;
    const double rho = fluid.density, nu = fluid.viscosity / rho;
    k_inflow = omega_inflow = 0;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      const BoundaryCondition &bc = boundaries.of_face(f);
      if (boundaries.kind(f) == Kind::wall)
        {
          const double d = mesh.distance_to_face(f);
          k_b[f] = 0, omega_b[f] = wall_omega_factor * 6 * nu / (beta_1 * d * d);
        }
      else if (s.flux[f] < 0 && (boundaries.kind(f) == Kind::velocity_inlet || boundaries.is_pressure_boundary(f)))
        {
          const double u_n = -s.flux[f] / (rho * mesh.face_area[f]);
          if (bc.turbulence_profile)
            {
              const auto [k_in, epsilon_in] = bc.turbulence_profile(mesh.face_center[f]);
              k_b[f] = k_in, omega_b[f] = epsilon_in / (beta_star * std::max(k_in, vanishing));
            }
          else
            {
              k_b[f] = 1.5 * std::pow(bc.turbulence_intensity * u_n, 2);
              omega_b[f] = std::sqrt(k_b[f]) / (std::pow(beta_star, 0.25) * bc.turbulence_length);
            }
          k_inflow = std::max(k_inflow, k_b[f]), omega_inflow = std::max(omega_inflow, omega_b[f]);
        }
      else
        k_b[f] = k[P], omega_b[f] = omega[P];
    });
  }

  void KOmegaSST::blending(const std::vector<Vector2> &grad_k, const std::vector<Vector2> &grad_ln_omega, double omega_floor)
  {
    const double rho = fluid.density, nu = fluid.viscosity / rho;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const double y = wall_distance[c], kc = std::max(k[c], 0.0), w = std::max(omega[c], omega_floor);
        const double cross = std::max(2 * rho * sigma_omega2 * grad_k[c].dot(grad_ln_omega[c]), cross_diffusion_floor);
        const double turbulent_scale = std::sqrt(kc) / (beta_star * w * y), viscous_scale = 500 * nu / (y * y * w);
        const double arg1 = std::min(std::max(turbulent_scale, viscous_scale), 4 * rho * sigma_omega2 * kc / (cross * y * y));
        F1[c] = std::tanh(std::pow(arg1, 4));
        const double arg2 = std::max(2 * turbulent_scale, viscous_scale);
        F2[c] = std::tanh(arg2 * arg2);
      }
  }

  TurbulenceResiduals KOmegaSST::correct(const FlowState &s, const std::vector<double> &convecting_flux,
                                         const TimeLevel *time)
  {
    const std::size_t n = mesh.n_cells(), nf = mesh.n_faces();
    const double rho = fluid.density, mu = fluid.viscosity, alpha = settings.turbulence_relaxation;
    const bool axisymmetric = mesh.geometry == Geometry::axisymmetric;
    TurbulenceResiduals r;

    double k_inflow = 0, omega_inflow = 0;
    boundary_values(s, k_inflow, omega_inflow);
    // a start from nothing or from laminar fields: as the k-epsilon models (k_epsilon.cc)
    if (*std::max_element(k.begin(), k.end()) <= 0)
      {
        const double L = boundaries.of_patch(0).turbulence_length;
        double k_start_max = 0, omega_start_max = 0;
        for (std::size_t c = 0; c < n; ++c)
          {
            k[c] = std::max(k_inflow, 1.5 * std::pow(seed_intensity * std::hypot(s.u[c], s.v[c]), 2));
            omega[c] = std::max(omega_inflow, std::sqrt(k[c]) / (std::pow(beta_star, 0.25) * L));
            k_start_max = std::max(k_start_max, k[c]), omega_start_max = std::max(omega_start_max, omega[c]);
          }
        if (k_inflow <= 0)
          k_inflow = k_start_max, omega_inflow = omega_start_max;
        boundary_values(s, k_inflow, omega_inflow);
      }
    const double k_floor = floor_fraction * std::max(k_inflow, *std::max_element(k.begin(), k.end()));
    const double omega_floor = floor_fraction * std::max(omega_inflow, *std::max_element(omega.begin(), omega.end()));

    // S^2 = 2 S_ij S_ij and the production mu_t S^2
    const std::vector<Vector2> gu = mesh.gradient(s.u, s.u_b), gv = mesh.gradient(s.v, s.v_b);
    std::vector<double> strain_squared(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        double G = 2 * (gu[c].x() * gu[c].x() + gv[c].y() * gv[c].y()) + std::pow(gu[c].y() + gv[c].x(), 2);
        if (axisymmetric)
          G += 2 * std::pow(s.v[c] / mesh.cell_center[c].y(), 2);
        strain_squared[c] = G;
      }
    // grad k . grad omega / omega of F1 and the cross-diffusion as grad k . grad ln omega: the same
    // term, but bounded where omega changes by orders of magnitude between cells (the wall layer, a
    // cavity's edge), where the quotient of omega's gradient and a cell's own omega amplified the
    // difference from one iteration to the next (omega swung between its floor and 1e12/s in a
    // cavitating orifice)
    std::vector<double> ln_omega(n), ln_omega_b(nf, 0.0);
    for (std::size_t c = 0; c < n; ++c)
      ln_omega[c] = std::log(std::max(omega[c], omega_floor));
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) { ln_omega_b[f] = std::log(std::max(omega_b[f], omega_floor)); });
    const std::vector<Vector2> grad_k = mesh.gradient(k, k_b), grad_ln_omega = mesh.gradient(ln_omega, ln_omega_b);
    blending(grad_k, grad_ln_omega, omega_floor);

    // face diffusivities mu + sigma mu_t with the blended sigma of the cells
    std::vector<double> gamma(nf);
    auto diffusivity = [&](double inner, double outer) {
      std::vector<double> sigma(n);
      for (std::size_t c = 0; c < n; ++c)
        sigma[c] = blend(F1[c], inner, outer);
      mesh.for_each_face([&](std::size_t f, unsigned int, unsigned int) { gamma[f] = mu + mesh.interpolate(f, sigma) * (mu_face[f] - mu); },
                         [&](std::size_t f, unsigned int P) { gamma[f] = mu + sigma[P] * (mu_face[f] - mu); });
    };
    double scale = 0;
    const double k_level = std::max(k_inflow, level_fraction * *std::max_element(k.begin(), k.end()));
    const double omega_level = std::max(omega_inflow, level_fraction * *std::max_element(omega.begin(), omega.end()));
    std::vector<double> level(n);

    // k: P~ as the source, beta* rho omega k as an implicit sink
    diffusivity(sigma_k1, sigma_k2);
    k_equation.assemble_convection_diffusion(k, k_b, gamma, convecting_flux, boundaries, settings.convection);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c], w = std::max(omega[c], omega_floor);
        const double production = std::min(mu_t[c] * strain_squared[c], production_limit * beta_star * rho * std::max(k[c], 0.0) * w);
        k_equation.diagonal[c] += beta_star * rho * w * V;
        k_equation.b[c] += production * V;
      }
    if (time)
      add_time_term(k_equation, *time, 0);
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(k[c], k_level);
    r.k = k_equation.relax(k, alpha, level, scale);
    r.k /= std::max(scale, vanishing);
    k_equation.solve(k, settings, settings.turbulence_solver, "k");

    // omega: alpha rho S^2 as the source, beta rho omega^2 as an implicit sink, the cross-diffusion a
    // source where positive, an implicit sink where negative
    diffusivity(sigma_omega1, sigma_omega2);
    omega_equation.assemble_convection_diffusion(omega, omega_b, gamma, convecting_flux, boundaries, settings.convection);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c], w = std::max(omega[c], omega_floor);
        omega_equation.diagonal[c] += blend(F1[c], beta_1, beta_2) * rho * w * V;
        omega_equation.b[c] += blend(F1[c], alpha_1, alpha_2) * rho * strain_squared[c] * V;
        const double cross = 2 * (1 - F1[c]) * rho * sigma_omega2 * grad_k[c].dot(grad_ln_omega[c]);
        if (cross > 0)
          omega_equation.b[c] += cross * V;
        else
          omega_equation.diagonal[c] -= cross / w * V;
      }
    if (time)
      add_time_term(omega_equation, *time, 1);
    // the wall cells: omega = 6 nu/(beta_1 y^2), their rows a_P (omega - that)
    {
      const double nu = mu / rho;
      std::vector<char> held(n, 0);
      for (const auto &[c, y] : wall_cells)
        {
          held[c] = 1;
          omega_equation.b[c] = omega_equation.diagonal[c] * 6 * nu / (beta_1 * y * y);
        }
      const int *inner = omega_equation.A.innerIndexPtr(), *outer = omega_equation.A.outerIndexPtr();
      double *value = omega_equation.A.valuePtr();
      for (std::size_t row = 0; row < n; ++row)
        for (int j = outer[row]; j < outer[row + 1]; ++j)
          if (held[row] && static_cast<std::size_t>(inner[j]) != row)
            value[j] = 0;
    }
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(omega[c], omega_level);
    r.epsilon = omega_equation.relax(omega, alpha, level, scale);
    r.epsilon /= std::max(scale, vanishing);
    omega_equation.solve(omega, settings, settings.turbulence_solver, "omega");

    // bounded, then mu_t = rho a1 k / max(a1 omega, S F2) (relaxed, at most the limit)
    const double mu_t_limit = viscosity_ratio_limit * mu;
    cells_at_limit = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        k[c] = std::max(k[c], k_floor);
        omega[c] = std::max(omega[c], omega_floor);
        const double target = rho * a1 * k[c] / std::max({a1 * omega[c], std::sqrt(strain_squared[c]) * F2[c], vanishing});
        cells_at_limit += target > mu_t_limit;
        mu_t[c] += settings.turbulent_viscosity_relaxation * (std::min(target, mu_t_limit) - mu_t[c]);
      }
    update_face_viscosity();
    return r;
  }

  void KOmegaSST::store(FlowFields &f) const
  {
    f.turbulent = true;
    f.k = k, f.turbulent_viscosity = mu_t;
    f.epsilon.resize(k.size());
    for (std::size_t c = 0; c < k.size(); ++c)
      f.epsilon[c] = beta_star * k[c] * omega[c];
  }

  void KOmegaSST::restore(const FlowFields &o)
  {
    if (o.turbulent)
      {
        k = o.k, mu_t = o.turbulent_viscosity;
        for (std::size_t c = 0; c < k.size(); ++c)
          omega[c] = o.epsilon[c] / (beta_star * std::max(k[c], vanishing));
      }
    else // from laminar fields: the model seeds itself at its next step
      std::fill(k.begin(), k.end(), 0.0), std::fill(omega.begin(), omega.end(), 0.0),
        std::fill(mu_t.begin(), mu_t.end(), 0.0);
    update_face_viscosity();
  }

  /// velocities by sqrt(s): omega, a rate U/L, by sqrt(s)
  void KOmegaSST::scale_pressure_level(double s) { scale_two_equation_fields(s, k, k_b, omega, omega_b, std::sqrt(s)); }

  std::vector<std::vector<double>> KOmegaSST::transported_fields() const { return {k, omega}; }

  std::vector<std::vector<double> *> KOmegaSST::accelerated_fields() { return {&k, &omega, &mu_t}; }

  void KOmegaSST::bound_accelerated(const std::vector<std::vector<double>> &before)
  {
    bound_two_equation_fields(k, omega, before);
  }

  std::vector<std::pair<std::string, const std::vector<double> *>> KOmegaSST::output_fields() const
  {
    return {{"k", &k}, {"omega", &omega}, {"turbulent_viscosity", &mu_t}, {"F1", &F1}};
  }
} // namespace servodrift::flow
