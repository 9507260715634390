// SimplecSolver::solve_newton: the steady discrete equations of the SIMPLEC solver as one residual
// R(x) = 0 of all unknowns, solved by Newton-PTC (newton_ptc.h) with a Jacobian of finite differences
// coloured by the stencil (doc/method.md, "Newton-PTC"). Laminar and single phase for now.
//
// The unknowns, in this order:
//   u, v, p per cell;
//   F per face: the face flux, an unknown of its own as in SIMPLEC, where the momentum equations
//     convect with F and Rhie-Chow's D = V/a_P depends on F through a_P;
//   p_b per boundary face that is not a pressure boundary: the pressure extrapolated with the
//     least-squares gradient, which itself reads p_b (SIMPLEC lags it by an iteration).
// The equations, one per unknown:
//   momentum   A(F) u - b(u, p) = 0, the assembled equations of momentum_equation.h (relaxation
//              changes A and b but not A u - b at the current u);
//   continuity sum_f F_f = 0 per cell;
//   face flux  F_f - RC_f(u, v, p, p_b; D(F)) = 0 (rhie_chow.h; walls F = 0; velocity inlets F_f
//              their given flux);
//   wall p     p_b - max(p_P + grad p_P . (x_f - x_P), p_floor) = 0.
#include "flow/fv/continuity.h"
#include "flow/fv/newton_ptc.h"
#include "flow/fv/rhie_chow.h"
#include "flow/fv/simplec_implementation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <stdexcept>

namespace servodrift::flow
{
  namespace
  {
    /// The widest reach of an unknown into the equations, in cells (face
    /// neighbours): a momentum row reads the limited gradient of its upwind
    /// neighbour, whose limiter reads that neighbour's neighbours; a face-flux row
    /// reads the pressure gradients of its two cells.
    constexpr unsigned int stencil_reach = 2;
    /// the finite-difference step relative to an unknown's size (about sqrt of
    /// double's epsilon, a little larger for residuals that sum many terms)
    constexpr double relative_step = 1e-7;
    /// the floor of a block's typical size and of the norm's scales, relative to the driven flow's
    constexpr double scale_floor = 1e-3;
  } // namespace

  // a nested class of SimplecSolver: it works on the solver's units
  class SimplecSolver::NewtonProblem : public PtcProblem
  {
  public:
    explicit NewtonProblem(SimplecSolver::Implementation &d);
    void pack(Eigen::VectorXd &x) const;
    bool residual(const Eigen::VectorXd &x, Eigen::VectorXd &R) override;
    void jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &R, Eigen::SparseMatrix<double> &J) override;
    void pseudo_time_mass(const Eigen::VectorXd &x, Eigen::VectorXd &P) override;
    double norm(const Eigen::VectorXd &R) const override;
    unsigned int colours() const { return n_colours; }

  private:
    void colour();
    SimplecSolver::Implementation &d;
    const FvMesh &mesh;
    std::size_t n, nf, n_unknowns;
    std::size_t pressure_offset, flux_offset, wall_offset;
    std::vector<std::size_t> extrapolated_face; ///< faces whose p_b is an unknown, in unknown order
    // per unknown: the rows that may depend on it (CSR), and its colour
    std::vector<std::size_t> reach_offset, reach_row;
    std::vector<char> in_pattern; ///< per reach entry: in the Jacobian's pattern
    std::vector<unsigned int> colour_of;
    unsigned int n_colours = 0;
    // the scales of the last residual at the unperturbed state
    double momentum_scale = 1, throughput = 1, pressure_scale = 1;
    /// the driven flow's scales (constructor): the floors of the steps and of the norm's scales, so
    /// that a field at rest has both
    double reference_pressure = 0, reference_speed = 0, reference_flux = 0;

  public:
    double limiter_hold_residual = 0; ///< see SimplecSolver::solve_newton
    bool limiter_held = false;        ///< from near the solution on (jacobian)
  };

  SimplecSolver::NewtonProblem::NewtonProblem(SimplecSolver::Implementation &d_)
    : d(d_)
    , mesh(d_.mesh)
    , n(mesh.n_cells())
    , nf(mesh.n_faces())
  {
    // the scales of the flow that the boundaries drive (what a field at rest has none of): the
    // largest boundary pressure, its Bernoulli speed or the largest given velocity, and their flux
    double largest_area = 0;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      if (!d.boundaries.is_pressure_boundary(f))
        extrapolated_face.push_back(f), reference_speed = std::max(reference_speed, d.boundaries.prescribed_velocity(f).norm());
      else
        reference_pressure = std::max(reference_pressure, std::abs(d.boundaries.of_face(f).pressure));
      largest_area = std::max(largest_area, mesh.face_area[f]);
    });
    reference_speed = std::max(reference_speed, std::sqrt(2 * reference_pressure / d.fluid.density));
    reference_pressure = std::max(reference_pressure, 0.5 * d.fluid.density * reference_speed * reference_speed);
    reference_flux = d.fluid.density * reference_speed * largest_area;
    pressure_offset = 2 * n, flux_offset = 3 * n, wall_offset = 3 * n + nf;
    n_unknowns = wall_offset + extrapolated_face.size();
    colour();
  }

  void SimplecSolver::NewtonProblem::colour()
  {
    // the cells of each unknown and each row (the same sets: one equation per
    // unknown)
    std::vector<std::size_t> cell_offset{0};
    std::vector<unsigned int> cells;
    for (std::size_t i = 0; i < 3 * n; ++i)
      cells.push_back(static_cast<unsigned int>(i % n)), cell_offset.push_back(cells.size());
    for (std::size_t f = 0; f < nf; ++f)
      {
        cells.push_back(mesh.owner[f]);
        if (mesh.neighbour[f] >= 0)
          cells.push_back(static_cast<unsigned int>(mesh.neighbour[f]));
        cell_offset.push_back(cells.size());
      }
    for (std::size_t f : extrapolated_face)
      cells.push_back(mesh.owner[f]), cell_offset.push_back(cells.size());
    // the rows attached to each cell
    std::vector<std::vector<std::size_t>> rows_of_cell(n);
    for (std::size_t i = 0; i < n_unknowns; ++i)
      for (std::size_t k = cell_offset[i]; k < cell_offset[i + 1]; ++k)
        rows_of_cell[cells[k]].push_back(i);
    // per unknown: the rows attached to a cell within stencil_reach of its cells
    // (breadth first)
    std::vector<unsigned int> distance(n, ~0u);
    std::vector<unsigned int> visited;
    std::vector<char> row_seen(n_unknowns, 0);
    reach_offset.assign(1, 0);
    for (std::size_t j = 0; j < n_unknowns; ++j)
      {
        std::queue<unsigned int> front;
        for (std::size_t k = cell_offset[j]; k < cell_offset[j + 1]; ++k)
          if (distance[cells[k]] != 0)
            distance[cells[k]] = 0, front.push(cells[k]), visited.push_back(cells[k]);
        while (!front.empty())
          {
            const unsigned int c = front.front();
            front.pop();
            for (std::size_t i : rows_of_cell[c])
              if (!row_seen[i])
                row_seen[i] = 1, reach_row.push_back(i);
            if (distance[c] == stencil_reach)
              continue;
            for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
              if (const int o = mesh.cell_face_other[k]; o >= 0 && distance[o] == ~0u)
                distance[o] = distance[c] + 1, front.push(o), visited.push_back(o);
          }
        for (unsigned int c : visited)
          distance[c] = ~0u;
        visited.clear();
        for (std::size_t k = reach_offset.back(); k < reach_row.size(); ++k)
          row_seen[reach_row[k]] = 0;
        reach_offset.push_back(reach_row.size());
      }
    in_pattern.assign(reach_row.size(), 0);
    // greedy colouring: two unknowns of one colour never reach the same row
    std::vector<std::vector<std::uint64_t>> used(n_unknowns); // per row: a bitset of the colours reaching it
    colour_of.assign(n_unknowns, 0);
    std::vector<std::uint64_t> forbidden;
    for (std::size_t j = 0; j < n_unknowns; ++j)
      {
        forbidden.assign((n_colours + 64) / 64 + 1, 0);
        for (std::size_t k = reach_offset[j]; k < reach_offset[j + 1]; ++k)
          {
            const auto &u = used[reach_row[k]];
            for (std::size_t w = 0; w < u.size(); ++w)
              forbidden[w] |= u[w];
          }
        unsigned int c = 0;
        while (forbidden[c / 64] >> (c % 64) & 1)
          ++c;
        colour_of[j] = c;
        n_colours = std::max(n_colours, c + 1);
        for (std::size_t k = reach_offset[j]; k < reach_offset[j + 1]; ++k)
          {
            auto &u = used[reach_row[k]];
            if (u.size() <= c / 64)
              u.resize(c / 64 + 1, 0);
            u[c / 64] |= std::uint64_t(1) << (c % 64);
          }
      }
  }

  void SimplecSolver::NewtonProblem::pack(Eigen::VectorXd &x) const
  {
    const FlowState &s = d.state;
    x.resize(n_unknowns);
    for (std::size_t c = 0; c < n; ++c)
      x[c] = s.u[c], x[n + c] = s.v[c], x[pressure_offset + c] = s.p[c];
    for (std::size_t f = 0; f < nf; ++f)
      x[flux_offset + f] = s.flux[f];
    for (std::size_t k = 0; k < extrapolated_face.size(); ++k)
      x[wall_offset + k] = s.p_b[extrapolated_face[k]];
  }

  bool SimplecSolver::NewtonProblem::residual(const Eigen::VectorXd &x, Eigen::VectorXd &R)
  {
    if (!x.allFinite())
      return false;
    FlowState &s = d.state;
    for (std::size_t c = 0; c < n; ++c)
      s.u[c] = x[c], s.v[c] = x[n + c], s.p[c] = x[pressure_offset + c];
    for (std::size_t f = 0; f < nf; ++f)
      s.flux[f] = x[flux_offset + f];
    d.boundaries.update_inflow_speeds(s.flux);
    d.update_boundary_values();
    for (std::size_t k = 0; k < extrapolated_face.size(); ++k)
      s.p_b[extrapolated_face[k]] = x[wall_offset + k];
    mesh.gradient(s.p, s.p_b, s.grad_p);
    R.resize(n_unknowns);
    const double floor = d.cavitation.pressure_floor();
    for (std::size_t k = 0; k < extrapolated_face.size(); ++k)
      {
        const std::size_t f = extrapolated_face[k];
        const unsigned int P = mesh.owner[f];
        R[wall_offset + k] =
            s.p_b[f] - std::max(s.p[P] + s.grad_p[P].dot(mesh.face_center[f] - mesh.cell_center[P]), floor);
      }
    const MomentumEquation::Residuals m = d.momentum.assemble(s, d.boundaries, *d.turbulence, s.flux);
    // at least a thousandth of the driven flow's sum a_P |u| (a field at rest has none)
    double diagonal_sum = 0;
    for (double a : d.momentum.component(0).diagonal)
      diagonal_sum += a;
    momentum_scale = std::max({m.scale, scale_floor * reference_speed * diagonal_sum, vanishing});
    for (int i = 0; i < 2; ++i)
      {
        const FvMatrix &eq = d.momentum.component(i);
        const Eigen::Map<const Eigen::VectorXd> phi((i == 0 ? s.u : s.v).data(), n);
        R.segment(i * n, n) = eq.A * phi - eq.b;
      }
    const std::vector<double> F_rc = rhie_chow_fluxes(mesh, d.fluid.density, s, d.momentum.D(), d.boundaries);
    std::vector<double> inlet(nf, 0.0);
    d.boundaries.set_velocity_inlet_fluxes(inlet);
    R.segment(pressure_offset, n).setZero();
    for (std::size_t f = 0; f < nf; ++f)
      {
        const bool given = mesh.neighbour[f] < 0 && d.boundaries.kind(f) == BoundaryCondition::Kind::velocity_inlet;
        R[flux_offset + f] = s.flux[f] - (given ? inlet[f] : F_rc[f]);
        R[pressure_offset + mesh.owner[f]] += s.flux[f];
        if (mesh.neighbour[f] >= 0)
          R[pressure_offset + mesh.neighbour[f]] -= s.flux[f];
      }
    if (!d.boundaries.has_pressure_boundary())
      R[pressure_offset] = s.p[0]; // p defined up to a constant: pinned in the first cell
    throughput = std::max({continuity_reference(mesh, s.flux, d.boundaries.velocity_inlet_inflow()),
                           scale_floor * reference_flux, vanishing});
    double largest_p = vanishing;
    for (double p : s.p)
      largest_p = std::max(largest_p, std::abs(p));
    pressure_scale = largest_p;
    return R.allFinite();
  }

  double SimplecSolver::NewtonProblem::norm(const Eigen::VectorXd &R) const
  {
    // each block as the solver's scaled residuals: momentum by sum a_P |u|,
    // continuity and face fluxes by the throughput, wall pressures by the largest
    // pressure (per face)
    const double u = R.segment(0, n).lpNorm<1>() / momentum_scale, v = R.segment(n, n).lpNorm<1>() / momentum_scale;
    const double c = R.segment(pressure_offset, n).lpNorm<1>() / throughput;
    const double F = R.segment(flux_offset, nf).lpNorm<1>() / throughput;
    const double w = extrapolated_face.empty()
                         ? 0.0
                         : R.segment(wall_offset, extrapolated_face.size()).lpNorm<Eigen::Infinity>() / pressure_scale;
    return std::max({u, v, c, F, w});
  }

  void SimplecSolver::NewtonProblem::pseudo_time_mass(const Eigen::VectorXd &, Eigen::VectorXd &P)
  {
    // the momentum equations' own diagonal a_P (of the last residual at the
    // unperturbed state): CFL 1 is then the step of velocity relaxation 1/2
    P.setZero(n_unknowns);
    for (int i = 0; i < 2; ++i)
      for (std::size_t c = 0; c < n; ++c)
        P[i * n + c] = d.momentum.component(i).diagonal[c];
  }

  void SimplecSolver::NewtonProblem::jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &R,
                                              Eigen::SparseMatrix<double> &J)
  {
    // Near the solution the convection limiter is held at its values of x (as SIMPLEC's iteration
    // control does where it hovers, and SU2's and FUN3D's frozen limiters): Barth-Jespersen's min is
    // not differentiable, and Newton hovers where it switches between faces. Held at x, the residual
    // at x is the same; the last assembly may have been a rejected trial's, hence x's first.
    if (!limiter_held && norm(R) < limiter_hold_residual)
      {
        Eigen::VectorXd at_x;
        residual(x, at_x);
        d.momentum.hold_limiters(true);
        limiter_held = true;
      }
    // typical sizes per block: a step relative to the block's largest value where
    // x_j is small
    const double speed = std::max(x.segment(0, 2 * n).lpNorm<Eigen::Infinity>(), scale_floor * reference_speed);
    const double pressure = std::max(x.segment(pressure_offset, n).lpNorm<Eigen::Infinity>(), scale_floor * reference_pressure);
    const double flux = std::max(x.segment(flux_offset, nf).lpNorm<Eigen::Infinity>(), scale_floor * reference_flux);
    auto typical = [&](std::size_t j) {
      return j < pressure_offset ? speed : j < flux_offset ? pressure : j < wall_offset ? flux : pressure;
    };
    std::vector<std::vector<std::size_t>> of_colour(n_colours);
    for (std::size_t j = 0; j < n_unknowns; ++j)
      of_colour[colour_of[j]].push_back(j);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd xp = x, Rp(n_unknowns);
    std::vector<double> step(n_unknowns);
    for (const auto &group : of_colour)
      {
        for (std::size_t j : group)
          {
            step[j] = relative_step * std::max(std::abs(x[j]), typical(j));
            // the step as the difference of representable numbers, so that (x + h) -
            // x = h exactly
            xp[j] = x[j] + step[j];
            step[j] = xp[j] - x[j];
          }
        residual(xp, Rp);
        for (std::size_t j : group)
          {
            for (std::size_t k = reach_offset[j]; k < reach_offset[j + 1]; ++k)
              {
                const std::size_t i = reach_row[k];
                const double value = (Rp[i] - R[i]) / step[j];
                // an entry once seen stays in the pattern (zero or not), so that the LU's
                // symbolic analysis is kept from one Jacobian to the next
                if (value != 0 || i == j)
                  in_pattern[k] = 1;
                if (in_pattern[k])
                  entries.emplace_back(i, j, value);
              }
            xp[j] = x[j];
          }
      }
    J.resize(n_unknowns, n_unknowns);
    J.setFromTriplets(entries.begin(), entries.end());
    Eigen::VectorXd restore;
    residual(x, restore); // the solver's state (and the scales) back at x
  }

  PtcReport SimplecSolver::solve_newton(const PtcSettings &settings, double limiter_hold_residual)
  {
    auto &d = *impl;
    if (d.turbulence->turbulent() || d.cavitation.enabled())
      throw std::invalid_argument("flow: Newton-PTC is laminar and single phase for now");
    d.forget_time_levels();
    NewtonProblem problem(d);
    problem.limiter_hold_residual = limiter_hold_residual;
    Eigen::VectorXd x;
    problem.pack(x);
    PtcReport report = solve_ptc(problem, x, settings);
    Eigen::VectorXd R;
    problem.residual(x, R); // the state, its boundary values and gradients at the final x
    report.limiter_held = problem.limiter_held;
    d.momentum.hold_limiters(false);
    report.colours = problem.colours();
    return report;
  }
} // namespace servodrift::flow
