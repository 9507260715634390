#include "flow/fv/coupled_step.h"

#include "flow/fv/continuity.h"
#include "flow/fv/rhie_chow.h"

#include <Eigen/SparseCore>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace servodrift::flow
{
  struct CoupledStep::System
  {
    /// the entries, the same (zeros included) at every assembly: the pattern is fixed per mesh
    std::vector<Eigen::Triplet<double>> entries;
    SparseMatrix matrix;
    std::vector<std::ptrdiff_t> position; ///< per entry: its place in the matrix's values
    Eigen::UmfPackLU<SparseMatrix> lu;
    bool analyzed = false;
  };

  CoupledStep::CoupledStep(const FvMesh &mesh_, double density_)
    : mesh(mesh_)
    , density(density_)
    , system(std::make_unique<System>())
  {}

  CoupledStep::~CoupledStep() = default;

  double CoupledStep::solve(FlowState &s, const MomentumEquation &momentum, const BoundaryConditions &boundaries,
                            CavitationModel &cavitation, double relaxation, double &throughput)
  {
    const std::size_t n = mesh.n_cells();
    const double rho = density;
    const std::vector<double> &D = momentum.D();
    const std::vector<double> F_now = rhie_chow_fluxes(mesh, rho, s, D, boundaries);
    throughput = continuity_reference(mesh, F_now, boundaries.velocity_inlet_inflow());
    const double sum = liquid_imbalance_sum(cell_mass_imbalance(mesh, F_now, cavitation), cavitation);

    // rows whose continuity is replaced by a given pressure: cavitating cells, and in a closed domain
    // (p defined up to a constant; the continuity rows sum to zero) the first cell
    std::vector<char> pinned(n, 0);
    for (std::size_t c = 0; c < n; ++c)
      pinned[c] = cavitation.cell_cavitates(c);
    if (!boundaries.has_pressure_boundary())
      pinned[0] = 1;

    auto &t = system->entries;
    t.clear();
    Eigen::VectorXd rhs(3 * n);
    const std::size_t pressure = 2 * n; // offset of p in the unknowns (u, v, p)
    // momentum: the relaxed equations, and V G_int(p) implicit
    for (int component = 0; component < 2; ++component)
      {
        const FvMatrix &eq = momentum.component(component);
        const std::size_t offset = component * n;
        for (int row = 0; row < eq.A.outerSize(); ++row)
          for (RowMajorMatrix::InnerIterator it(eq.A, row); it; ++it)
            t.emplace_back(offset + it.row(), offset + it.col(), it.value());
        rhs.segment(offset, n) = eq.b;
      }
    const auto &coefficient = mesh.gradient_coefficients();
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
        {
          const int other = mesh.cell_face_other[k];
          if (other < 0)
            continue;
          for (int component = 0; component < 2; ++component)
            {
              const double a = mesh.cell_volume[c] * coefficient[k][component];
              t.emplace_back(component * n + c, pressure + other, a);
              t.emplace_back(component * n + c, pressure + c, -a);
              rhs[component * n + c] += a * (s.p[other] - s.p[c]);
            }
        }
    // continuity
    rhs.segment(pressure, n).setZero();
    auto continuity = [&](std::size_t row, std::size_t column, double value) {
      t.emplace_back(pressure + row, column, pinned[row] ? 0.0 : value);
    };
    mesh.for_each_face(
      [&](std::size_t f, unsigned int P, unsigned int N) {
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f], m = cavitation.face_mixture_ratio(f, s.flux[f]);
        const double ax = rho * area * nrm.x(), ay = rho * area * nrm.y();
        const double w = mesh.face_weight(f);
        const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
        const double c_f = face_coefficient(mesh, f, D, rho);
        const double explicit_part = c_f * mesh.interpolate(f, s.grad_p).dot(d);
        for (const auto &[row, sign] : {std::pair<unsigned int, double>{P, m}, {N, -m}})
          {
            continuity(row, P, sign * w * ax), continuity(row, N, sign * (1 - w) * ax);
            continuity(row, n + P, sign * w * ay), continuity(row, n + N, sign * (1 - w) * ay);
            continuity(row, pressure + P, sign * c_f), continuity(row, pressure + N, -sign * c_f);
            rhs[pressure + row] -= sign * explicit_part;
          }
      },
      [&](std::size_t f, unsigned int P) {
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f], m = cavitation.face_mixture_ratio(f, s.flux[f]);
        const double ax = rho * area * nrm.x(), ay = rho * area * nrm.y();
        if (boundaries.is_pressure_boundary(f))
          {
            const Vector2 d = mesh.face_center[f] - mesh.cell_center[P];
            const double c_b = face_coefficient(mesh, f, D, rho);
            continuity(P, P, m * ax), continuity(P, n + P, m * ay), continuity(P, pressure + P, m * c_b);
            rhs[pressure + P] -= m * (-c_b * s.p_b[f] + c_b * s.grad_p[P].dot(d));
          }
        else if (boundaries.kind(f) == BoundaryCondition::Kind::velocity_inlet)
          rhs[pressure + P] -= m * s.flux[f];
      });
    for (std::size_t c = 0; c < n; ++c)
      {
        t.emplace_back(pressure + c, pressure + c, pinned[c] ? 1.0 : 0.0);
        if (pinned[c])
          rhs[pressure + c] = cavitation.cell_cavitates(c) ? cavitation.pressure_floor() : s.p[c];
      }

    SparseMatrix &M = system->matrix;
    if (!system->analyzed)
      {
        // once per mesh: the pattern (the entries are the same at every assembly), where each entry
        // goes in the value array, and the LU's symbolic analysis
        M.resize(3 * n, 3 * n);
        M.setFromTriplets(t.begin(), t.end());
        const int *inner = M.innerIndexPtr(), *outer = M.outerIndexPtr();
        system->position.resize(t.size());
        for (std::size_t k = 0; k < t.size(); ++k)
          system->position[k] = std::lower_bound(inner + outer[t[k].col()], inner + outer[t[k].col() + 1], t[k].row()) - inner;
        system->lu.analyzePattern(M);
        system->analyzed = true;
      }
    else
      {
        // the values in place (duplicates summed, as setFromTriplets does)
        double *value = M.valuePtr();
        std::fill(value, value + M.nonZeros(), 0.0);
        for (std::size_t k = 0; k < t.size(); ++k)
          value[system->position[k]] += t[k].value();
      }
    system->lu.factorize(M);
    if (system->lu.info() != Eigen::Success)
      throw std::runtime_error("UMFPACK could not factorise the coupled pressure-velocity matrix");
    const Eigen::VectorXd x = system->lu.solve(rhs);
    if (system->lu.info() != Eigen::Success || !x.allFinite())
      throw std::runtime_error("the coupled pressure-velocity solve failed");
    const std::vector<double> p_old = s.p;
    for (std::size_t c = 0; c < n; ++c)
      s.u[c] = x[c], s.v[c] = x[n + c], s.p[c] = x[pressure + c];
    // the fluxes of the solution (the lagged mean gradient and boundary pressures as in the system):
    // conservative to the LU's round-off
    s.flux = rhie_chow_fluxes(mesh, rho, s, D, boundaries);
    for (std::size_t c = 0; c < n; ++c)
      cavitation.set_cell_pressure(s.p, c, p_old[c] + relaxation * (s.p[c] - p_old[c]));
    return sum;
  }
} // namespace servodrift::flow
