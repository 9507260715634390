#include "flow/simplec.h"

#include "common/error.h"
#include "common/units.h"
#include "flow/anderson_acceleration.h"
#include "flow/gauss_seidel_preconditioner.h"
#include "flow/vtu_writer.h"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <iostream>
#include <set>
#include <stdexcept>

namespace servodrift::flow
{
  using Kind = BoundaryCondition::Kind;

  BoundaryCondition BoundaryCondition::wall(Vector2 moving)
  {
    BoundaryCondition b;
    b.kind = Kind::wall;
    b.velocity = [moving](const Vector2 &) { return moving; };
    return b;
  }

  BoundaryCondition BoundaryCondition::velocity_inlet(std::function<Vector2(const Vector2 &)> profile)
  {
    BoundaryCondition b;
    b.kind = Kind::velocity_inlet;
    b.velocity = std::move(profile);
    return b;
  }

  BoundaryCondition BoundaryCondition::total_pressure_inlet(double p0)
  {
    BoundaryCondition b;
    b.kind = Kind::total_pressure_inlet;
    b.pressure = p0;
    return b;
  }

  BoundaryCondition BoundaryCondition::pressure_outlet(double p)
  {
    BoundaryCondition b;
    b.kind = Kind::pressure_outlet;
    b.pressure = p;
    return b;
  }

  BoundaryCondition BoundaryCondition::axis()
  {
    BoundaryCondition b;
    b.kind = Kind::axis;
    return b;
  }

  BoundaryCondition BoundaryCondition::symmetry()
  {
    BoundaryCondition b;
    b.kind = Kind::symmetry;
    return b;
  }

  namespace
  {
    using SparseMatrix = Eigen::SparseMatrix<double>;
    using Cholesky = Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower>;

    /// Preconditions conjugate gradients with a Cholesky factorisation of a recent pressure matrix:
    /// the matrix changes slowly from one SIMPLEC iteration to the next, so an older factor solves
    /// the new system in a few iterations, and it is renewed only when they are no longer few.
    class FactorPreconditioner
    {
    public:
      using StorageIndex = int;
      enum
      {
        ColsAtCompileTime = Eigen::Dynamic,
        MaxColsAtCompileTime = Eigen::Dynamic
      };
      FactorPreconditioner() = default;
      template <typename M>
      FactorPreconditioner &analyzePattern(const M &) { return *this; }
      template <typename M>
      FactorPreconditioner &factorize(const M &) { return *this; }
      template <typename M>
      FactorPreconditioner &compute(const M &) { return *this; }
      template <typename Rhs>
      Rhs solve(const Rhs &b) const { return factor->solve(b); }
      Eigen::ComputationInfo info() const { return Eigen::Success; }
      const Cholesky *factor = nullptr;
    };

    bool is_pressure_boundary(Kind k)
    {
      return k == Kind::pressure_outlet || k == Kind::total_pressure_inlet;
    }
  } // namespace

  struct SimplecSolver::Implementation
  {
    const FvMesh &mesh;
    FluidProperties fluid;
    FlowSolverParameters settings;
    std::vector<BoundaryCondition> patch_condition; ///< per patch
    std::vector<Kind> face_kind;                    ///< per face (interior: unused)
    std::vector<Vector2> prescribed_velocity;       ///< walls and velocity inlets, per face

    std::vector<double> u, v, p, flux;
    std::vector<double> u_b, v_b, p_b; ///< boundary face values (interior entries unused)
    /// Pressure boundaries: the normal velocity of an inflow from the last fluxes (< 0; 0 for an outflow)
    std::vector<double> inflow_speed;
    void update_inflow_speeds()
    {
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (mesh.neighbour[f] < 0 && is_pressure_boundary(face_kind[f]))
          inflow_speed[f] = std::min(flux[f], 0.0) / (fluid.density * mesh.face_area[f]);
    }
    std::vector<Vector2> grad_p;
    std::vector<double> D, D_simplec; ///< V/a_P and V/(a_P - sum a_nb)
    bool has_pressure_boundary = false;
    double reference_flux = 0;

    // sparse pattern: diagonal and one entry per side of each interior face
    SparseMatrix matrix_u, matrix_v, matrix_p;
    std::vector<std::ptrdiff_t> diagonal_index;     ///< per cell
    std::vector<std::ptrdiff_t> owner_row_index;    ///< per interior face: (owner, neighbour)
    std::vector<std::ptrdiff_t> neighbour_row_index; ///< per interior face: (neighbour, owner)
    Cholesky pressure_factor;
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, FactorPreconditioner> pressure_cg;
    bool have_pressure_factor = false;
    unsigned int last_cg_iterations = 0;
    Eigen::UmfPackLU<SparseMatrix> direct_u, direct_v;
    Eigen::BiCGSTAB<SparseMatrix, Eigen::IncompleteLUT<double>> iterative_ilu;
    Eigen::BiCGSTAB<SparseMatrix, Eigen::DiagonalPreconditioner<double>> iterative_jacobi;
    Eigen::BiCGSTAB<SparseMatrix, SymmetricGaussSeidelPreconditioner> iterative_gauss_seidel;
    std::vector<double> diag, off_sum, psi; // work arrays of the momentum assembly
    std::vector<Vector2> grad;

    // turbulence: k, epsilon~ (Launder-Sharma), the turbulent viscosity mu_t per cell, and the
    // effective viscosity mu + mu_t per face (the laminar mu at walls)
    bool turbulent = false;
    double viscosity_ratio_limit = 1e5; ///< mu_t <= this mu (set_turbulent_viscosity_limit)
    std::size_t cells_at_viscosity_limit = 0; ///< in the last turbulence step
    std::vector<double> k, epsilon, mu_t, k_b, epsilon_b, mu_face;
    SparseMatrix matrix_k, matrix_epsilon;

    Implementation(const FvMesh &mesh, const FluidProperties &fluid,
                   const std::map<std::string, BoundaryCondition> &boundaries, const FlowSolverParameters &settings);

    void setup_pattern();
    void update_boundary_values();
    double distance_to_face(std::size_t f) const
    {
      return (mesh.face_center[f] - mesh.cell_center[mesh.owner[f]]).dot(mesh.face_normal[f]);
    }
    std::vector<double> limiter(const std::vector<double> &phi, const std::vector<double> &phi_b,
                                const std::vector<Vector2> &grad) const;
    /// Convection (upwind, plus the bounded linear upwind correction) and diffusion (central, plus the
    /// non-orthogonal correction) of phi with the face diffusivities gamma: the off-diagonal values of
    /// A in place, the diagonal in `diag' (not yet in A), sum a_nb in `off_sum', the sources in b.
    /// Boundary faces: walls and velocity inlets hold phi_b (diffusion and inflow); at a pressure
    /// boundary an inflow carries phi_b in; axis and symmetry add nothing here.
    void assemble_transport(SparseMatrix &A, Eigen::VectorXd &b, const std::vector<double> &phi,
                            const std::vector<double> &phi_b, const std::vector<double> &gamma);
    /// Writes diag/alpha into A and the relaxation source into b; returns sum |b - A phi| before
    /// relaxation and in `scale' sum diag |scale_field|.
    double relax(SparseMatrix &A, Eigen::VectorXd &b, const std::vector<double> &phi, double alpha,
                 const std::vector<double> &scale_field, double &scale);
    double assemble_momentum(SparseMatrix &A, Eigen::VectorXd &b, const std::vector<double> &phi,
                             const std::vector<double> &phi_b, const std::vector<double> &other, int component,
                             double &scale);
    void solve_iteratively(SparseMatrix &A, Eigen::VectorXd &b, std::vector<double> &phi, const char *equation);
    // k-epsilon (issue 5): turbulent viscosity, its face values, and one step of the k and epsilon
    // equations; the two-layer model needs each cell's distance to the nearest wall
    std::vector<double> wall_distance;
    void compute_wall_distance();
    // Cavitation (equilibrium, mass-conserving): each cell is liquid (gamma = 1, p >= p_cav) or
    // cavitating (p = p_cav, gamma < 1); the mixture density rho (gamma + (1 - gamma) vapour ratio)
    // carries the mass. mass_flux = mixture density ratio (upwind) x flux.
    bool cavitation = false;
    double cavitation_pressure = -1e300;
    std::vector<double> liquid_fraction, mass_flux;
    std::vector<char> cavitating;
    double pressure_relaxation = 1; // alpha_p of this solve: the setting, lowered when a cycle is caught
    double mixture_ratio(std::size_t cell) const
    {
      return liquid_fraction[cell] + (1 - liquid_fraction[cell]) * settings.vapour_density_ratio;
    }
    /// The mixture density ratio carried by face f with volume flux F (upwind; an inflow is liquid).
    double face_mixture_ratio(std::size_t f, double F) const
    {
      if (!cavitation)
        return 1.0;
      if (mesh.neighbour[f] < 0)
        return F >= 0 ? mixture_ratio(mesh.owner[f]) : 1.0;
      return mixture_ratio(F >= 0 ? mesh.owner[f] : static_cast<unsigned int>(mesh.neighbour[f]));
    }
    void update_mass_flux()
    {
      mass_flux.resize(mesh.n_faces());
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        mass_flux[f] = face_mixture_ratio(f, flux[f]) * flux[f];
    }
    void update_liquid_fraction();
    /// A cell's new pressure: a cavitating cell holds p_cav, and a liquid one that would be stretched
    /// below the vapour pressure cavitates.
    void set_cell_pressure(std::size_t c, double pressure)
    {
      if (cavitation && (cavitating[c] || pressure < cavitation_pressure))
        p[c] = cavitation_pressure, cavitating[c] = 1;
      else
        p[c] = pressure;
    }
    const std::vector<double> &convecting_flux() const { return cavitation ? mass_flux : flux; }
    std::function<std::vector<double>()> monitor;
    unsigned int monitor_window = 50;
    double monitor_change = 1e-4;
    void update_face_viscosity();
    void turbulence_step(Residuals &r);
    void solve_momentum(SparseMatrix &A, Eigen::VectorXd &b, std::vector<double> &phi,
                        Eigen::UmfPackLU<SparseMatrix> &direct, bool first);
    std::vector<double> rhie_chow_fluxes() const;
    /// What the continuity residual is relative to: the velocity inlets' inflow or, in a
    /// pressure-driven flow, the current inflow or outflow of the fluxes F, whichever is larger (from
    /// rest, one of them can pass through nearly zero while the other has built up, and a residual
    /// relative to it would read as a divergence); in a closed domain the mean |F| of a face row.
    double throughput_of(const std::vector<double> &F) const
    {
      double inflow = 0, outflow = 0, circulation = 0;
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (mesh.neighbour[f] < 0)
          inflow += std::max(0.0, -F[f]), outflow += std::max(0.0, F[f]);
        else
          circulation += std::abs(F[f]);
      return reference_flux > 0               ? reference_flux :
             std::max(inflow, outflow) > 0 ? std::max(inflow, outflow) :
                                             circulation / std::sqrt(double(mesh.n_cells()));
    }
    double pressure_correction(std::vector<double> &flux_star);
    // Coupled pressure-velocity solution (`Pressure-velocity coupling = coupled'): one linear system
    // in (u, v, p), its pattern fixed per mesh (the same entries, zeros included, at every assembly)
    std::vector<Eigen::Triplet<double>> coupled_entries;
    SparseMatrix matrix_coupled;
    std::vector<std::ptrdiff_t> coupled_position; ///< per entry of coupled_entries: its place in the values
    Eigen::UmfPackLU<SparseMatrix> coupled_lu;
    bool coupled_analyzed = false;
    bool coupled_iterations = false; ///< this solve iterates coupled (the setting, or SIMPLEC stalled)
    double coupled_step(const Eigen::VectorXd &bu, const Eigen::VectorXd &bv, double &throughput);
    Residuals iterate(bool first);
    /// Cavitation, inflow speeds and turbulence after the new fluxes; the scaled residuals.
    Residuals finish_iteration(double ru, double rv, double scale, double imbalance, double throughput);

    // Anderson acceleration of the iteration (`Acceleration depth'): the state the next iteration
    // starts from, packed into one vector with each field divided by its own scale (set at a restart,
    // so that the least-squares problem weighs velocity, pressure and turbulence alike).
    std::vector<std::vector<double> *> accelerated_fields();
    std::vector<double> field_scales;
    Eigen::VectorXd pack_state();
    void unpack_state(const Eigen::VectorXd &x);
  };

  SimplecSolver::Implementation::Implementation(const FvMesh &mesh_, const FluidProperties &fluid_,
                                                const std::map<std::string, BoundaryCondition> &boundaries,
                                                const FlowSolverParameters &settings_)
    : mesh(mesh_)
    , fluid(fluid_)
    , settings(settings_)
  {
    if (!(fluid.density > 0))
      throw InputError("flow: density " + format_number(fluid.density) + " kg/m^3 must be > 0");
    if (!(fluid.viscosity > 0))
      throw InputError("flow: viscosity " + format_number(fluid.viscosity) + " Pa*s must be > 0");
    for (const auto &[name, bc] : boundaries)
      if (mesh.patch_index(name) < 0)
        {
          std::string known;
          for (const auto &n : mesh.patch_names)
            known += (known.empty() ? "" : ", ") + n;
          throw InputError(mesh.source + ": no boundary `" + name + "' (its boundaries: " + known + ")");
        }
    bool inlet = false, outlet = false, moving_wall = false;
    for (std::size_t k = 0; k < mesh.patch_names.size(); ++k)
      {
        const auto found = boundaries.find(mesh.patch_names[k]);
        if (found == boundaries.end())
          throw InputError(mesh.source + ": boundary `" + mesh.patch_names[k] + "' has no boundary condition");
        const BoundaryCondition &bc = found->second;
        if (bc.kind == Kind::axis && mesh.geometry != Geometry::axisymmetric)
          throw InputError(mesh.source + ": boundary `" + mesh.patch_names[k] + "' is an axis in a planar domain");
        patch_condition.push_back(bc);
        inlet = inlet || bc.kind == Kind::velocity_inlet || bc.kind == Kind::total_pressure_inlet;
        outlet = outlet || bc.kind == Kind::pressure_outlet;
        if (bc.kind == Kind::wall)
          for (unsigned int f : mesh.patch_faces[k])
            moving_wall = moving_wall || bc.velocity(mesh.face_center[f]).norm() > 0;
        has_pressure_boundary = has_pressure_boundary || is_pressure_boundary(bc.kind);
      }
    if (!inlet && !moving_wall)
      throw InputError(mesh.source + ": no inlet (and no moving wall) drives the flow");
    if (inlet && !outlet && !has_pressure_boundary)
      throw InputError(mesh.source + ": the flow has an inlet but no outlet");

    const std::size_t n = mesh.n_cells(), nf = mesh.n_faces();
    u.assign(n, 0), v.assign(n, 0), p.assign(n, 0), flux.assign(nf, 0);
    u_b.assign(nf, 0), v_b.assign(nf, 0), p_b.assign(nf, 0), inflow_speed.assign(nf, 0);
    grad_p.assign(n, Vector2::Zero());
    D.assign(n, 0), D_simplec.assign(n, 0);
    face_kind.assign(nf, Kind::wall);
    prescribed_velocity.assign(nf, Vector2::Zero());
    for (std::size_t f = 0; f < nf; ++f)
      if (mesh.neighbour[f] < 0)
        {
          const BoundaryCondition &bc = patch_condition[mesh.face_patch[f]];
          face_kind[f] = bc.kind;
          if (bc.kind == Kind::wall || bc.kind == Kind::velocity_inlet)
            prescribed_velocity[f] = bc.velocity(mesh.face_center[f]);
          if (bc.kind == Kind::velocity_inlet)
            flux[f] = fluid.density * prescribed_velocity[f].dot(mesh.face_normal[f]) * mesh.face_area[f];
        }
    // throughput: inflow through velocity inlets, else (pressure-driven) updated as it develops
    for (std::size_t f = 0; f < nf; ++f)
      if (mesh.neighbour[f] < 0 && face_kind[f] == Kind::velocity_inlet)
        reference_flux += std::max(0.0, -flux[f]);
    setup_pattern();
    turbulent = settings.turbulence != FlowSolverParameters::Turbulence::laminar;
    if (settings.turbulence == FlowSolverParameters::Turbulence::k_epsilon)
      compute_wall_distance();
    mu_t.assign(n, 0.0);
    k.assign(n, 0.0), epsilon.assign(n, 0.0), k_b.assign(nf, 0.0), epsilon_b.assign(nf, 0.0);
    liquid_fraction.assign(n, 1.0), cavitating.assign(n, 0);
    mass_flux = flux;
    update_face_viscosity();
    update_boundary_values();
  }

  void SimplecSolver::Implementation::setup_pattern()
  {
    const std::size_t n = mesh.n_cells();
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t c = 0; c < n; ++c)
      t.emplace_back(c, c, 1.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] >= 0)
        {
          t.emplace_back(mesh.owner[f], mesh.neighbour[f], 0.0);
          t.emplace_back(mesh.neighbour[f], mesh.owner[f], 0.0);
        }
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    auto position = [&A](std::size_t r, std::size_t c) {
      const int *inner = A.innerIndexPtr(), *outer = A.outerIndexPtr();
      return std::lower_bound(inner + outer[c], inner + outer[c + 1], static_cast<int>(r)) - inner;
    };
    diagonal_index.resize(n);
    for (std::size_t c = 0; c < n; ++c)
      diagonal_index[c] = position(c, c);
    owner_row_index.assign(mesh.n_faces(), -1);
    neighbour_row_index.assign(mesh.n_faces(), -1);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] >= 0)
        {
          owner_row_index[f] = position(mesh.owner[f], mesh.neighbour[f]);
          neighbour_row_index[f] = position(mesh.neighbour[f], mesh.owner[f]);
        }
    matrix_u = A, matrix_v = A, matrix_p = A, matrix_k = A, matrix_epsilon = A;
    pressure_factor.analyzePattern(matrix_p); // once per mesh
    if (pressure_factor.info() != Eigen::Success)
      throw std::runtime_error("flow: CHOLMOD symbolic analysis of the pressure equation failed");
    pressure_cg.preconditioner().factor = &pressure_factor;
  }

  void SimplecSolver::Implementation::update_boundary_values()
  {
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        if (mesh.neighbour[f] >= 0)
          continue;
        const unsigned int P = mesh.owner[f];
        const Vector2 &n = mesh.face_normal[f];
        const Vector2 uP(u[P], v[P]);
        Vector2 ub;
        switch (face_kind[f])
          {
            case Kind::wall:
            case Kind::velocity_inlet: ub = prescribed_velocity[f]; break;
            case Kind::symmetry: ub = uP - uP.dot(n) * n; break;
            case Kind::axis: ub = Vector2(u[P], 0.0); break;
            default: // pressure boundaries
              // outflow: zero gradient; inflow: normal to the face with the speed of its flux (a
              // zero gradient at an inflow would leave the cell's momentum equation without its
              // convective diagonal and the iteration unstable)
              ub = inflow_speed[f] < 0 ? Vector2(inflow_speed[f] * n) : uP;
          }
        u_b[f] = ub.x(), v_b[f] = ub.y();
        const BoundaryCondition &bc = patch_condition[mesh.face_patch[f]];
        if (is_pressure_boundary(face_kind[f]))
          {
            // Inflow comes from a reservoir at rest at the given pressure, through a total-pressure
            // inlet or back in through an outlet (entrainment): p = p_0 - rho u_n^2/2 with the
            // face's normal velocity from its flux, the form the pressure correction linearises.
            // Outflow leaves at the given static pressure.
            const double u_n = inflow_speed[f];
            p_b[f] = bc.pressure - 0.5 * fluid.density * u_n * u_n;
          }
        else // extrapolated with the last gradient (second order at walls: the wall pressure force)
          p_b[f] = std::max(p[P] + grad_p[P].dot(mesh.face_center[f] - mesh.cell_center[P]), cavitation_pressure);
      }
  }

  std::vector<double> SimplecSolver::Implementation::limiter(const std::vector<double> &phi,
                                                             const std::vector<double> &phi_b,
                                                             const std::vector<Vector2> &grad) const
  {
    // Barth-Jespersen: the reconstructed face values stay within the neighbours' range
    std::vector<double> psi(mesh.n_cells(), 1.0);
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        double lo = phi[c], hi = phi[c];
        for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
          {
            const double o = mesh.value_across(k, phi, phi_b);
            lo = std::min(lo, o), hi = std::max(hi, o);
          }
        for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
          {
            const double delta = grad[c].dot(mesh.cell_to_face[k]);
            if (delta > 1e-300)
              psi[c] = std::min(psi[c], std::min(1.0, (hi - phi[c]) / delta));
            else if (delta < -1e-300)
              psi[c] = std::min(psi[c], std::min(1.0, (lo - phi[c]) / delta));
          }
      }
    return psi;
  }

  void SimplecSolver::Implementation::assemble_transport(SparseMatrix &A, Eigen::VectorXd &b,
                                                         const std::vector<double> &phi,
                                                         const std::vector<double> &phi_b,
                                                         const std::vector<double> &gamma)
  {
    const std::size_t n = mesh.n_cells();
    double *value = A.valuePtr();
    std::fill(value, value + A.nonZeros(), 0.0);
    b.setZero(n);
    diag.assign(n, 0.0);
    off_sum.assign(n, 0.0);
    mesh.gradient(phi, phi_b, grad);
    const bool second_order = settings.convection == FlowSolverParameters::Convection::bounded_linear_upwind;
    if (second_order)
      psi = limiter(phi, phi_b, grad);

    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const unsigned int P = mesh.owner[f];
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f], F = convecting_flux()[f];
        if (mesh.neighbour[f] >= 0)
          {
            const unsigned int N = mesh.neighbour[f];
            const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
            // diffusion, over-relaxed split S = E + T with E along d: implicit gamma |E|/|d|, explicit T part
            const double Df = gamma[f] * area / nrm.dot(d);
            const double aPN = Df + std::max(-F, 0.0), aNP = Df + std::max(F, 0.0); // upwind convection
            value[owner_row_index[f]] = -aPN;
            value[neighbour_row_index[f]] = -aNP;
            diag[P] += aPN, diag[N] += aNP;
            off_sum[P] += aPN, off_sum[N] += aNP;
            const double w = mesh.face_weight(f);
            const Vector2 grad_f = w * grad[P] + (1 - w) * grad[N];
            const Vector2 T = area * nrm - area / nrm.dot(d) * d;
            const double nonorthogonal = gamma[f] * grad_f.dot(T);
            b[P] += nonorthogonal, b[N] -= nonorthogonal;
            if (second_order)
              {
                // deferred correction: F (phi_face,linear upwind - phi_upwind) moves to the source
                const unsigned int U = F >= 0 ? P : N;
                const double correction = F * psi[U] * grad[U].dot(mesh.face_center[f] - mesh.cell_center[U]);
                b[P] -= correction, b[N] += correction;
              }
          }
        else
          {
            double a = 0;
            switch (face_kind[f])
              {
                case Kind::wall:
                case Kind::velocity_inlet:
                  a = gamma[f] * area / distance_to_face(f) + std::max(-F, 0.0);
                  break;
                case Kind::pressure_outlet:
                case Kind::total_pressure_inlet:
                  a = std::max(-F, 0.0); // inflow carries the boundary value in; outflow leaves with the cell's
                  break;
                default: break; // axis (no area), symmetry (no flux; the momentum adds its own)
              }
            diag[P] += a;
            b[P] += a * phi_b[f];
          }
      }
  }

  double SimplecSolver::Implementation::relax(SparseMatrix &A, Eigen::VectorXd &b, const std::vector<double> &phi,
                                             double alpha, const std::vector<double> &scale_field, double &scale)
  {
    const std::size_t n = mesh.n_cells();
    double *value = A.valuePtr();
    for (std::size_t c = 0; c < n; ++c)
      value[diagonal_index[c]] = diag[c];
    Eigen::Map<const Eigen::VectorXd> x(phi.data(), n);
    const Eigen::VectorXd r = b - A * x;
    double residual = 0;
    scale = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        residual += std::abs(r[c]);
        scale += diag[c] * std::abs(scale_field[c]);
      }
    for (std::size_t c = 0; c < n; ++c)
      {
        value[diagonal_index[c]] = diag[c] / alpha;
        b[c] += (1 - alpha) / alpha * diag[c] * phi[c];
      }
    return residual;
  }

  /// Assembles the momentum equation of one component (0: x, 1: y) in place; returns the sum of
  /// |residual| of the current field (before relaxation), and in `scale' its normalisation.
  double SimplecSolver::Implementation::assemble_momentum(SparseMatrix &A, Eigen::VectorXd &b,
                                                          const std::vector<double> &phi,
                                                          const std::vector<double> &phi_b,
                                                          const std::vector<double> &other, int component,
                                                          double &scale)
  {
    const std::size_t n = mesh.n_cells();
    const double mu = fluid.viscosity;
    assemble_transport(A, b, phi, phi_b, mu_face);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] < 0 && face_kind[f] == Kind::symmetry)
        {
          // no shear: only the normal component diffuses towards zero (couples u and v)
          const unsigned int P = mesh.owner[f];
          const Vector2 &nrm = mesh.face_normal[f];
          const double a = mu_face[f] * mesh.face_area[f] / distance_to_face(f), nc = nrm[component],
                       no = nrm[1 - component];
          diag[P] += a * nc * nc;
          b[P] -= a * nc * no * other[P];
        }
    if (turbulent)
      {
        // the transpose part of the turbulent stress, div(mu_t (grad u)^T), explicitly: it vanishes
        // for a constant viscosity in planar flow, not for mu_t
        const std::vector<Vector2> grad_u = mesh.gradient(u, u_b), grad_v = mesh.gradient(v, v_b);
        for (std::size_t f = 0; f < mesh.n_faces(); ++f)
          if (mesh.neighbour[f] >= 0)
            {
              const unsigned int P = mesh.owner[f], N = mesh.neighbour[f];
              const double w = mesh.face_weight(f);
              const double mut = w * mu_t[P] + (1 - w) * mu_t[N];
              const Vector2 S = mesh.face_area[f] * mesh.face_normal[f];
              const double gu = w * grad_u[P][component] + (1 - w) * grad_u[N][component];
              const double gv = w * grad_v[P][component] + (1 - w) * grad_v[N][component];
              const double t = mut * (gu * S.x() + gv * S.y());
              b[P] += t, b[N] -= t;
            }
      }
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c];
        b[c] -= grad_p[c][component] * V; // pressure gradient
        if (component == 1 && mesh.geometry == Geometry::axisymmetric)
          {
            // hoop: -mu u_r/r^2 of the Laplacian form; -2 mu_t u_r/r^2 for the turbulent stress,
            // whose transpose part is explicit above
            const double r = mesh.cell_center[c].y();
            diag[c] += (mu + 2 * (turbulent ? mu_t[c] : 0.0)) * V / (r * r);
          }
      }
    std::vector<double> speed(n);
    for (std::size_t c = 0; c < n; ++c)
      speed[c] = std::hypot(u[c], v[c]);
    const double alpha = settings.velocity_relaxation;
    const double residual = relax(A, b, phi, alpha, speed, scale);
    if (component == 0)
      for (std::size_t c = 0; c < n; ++c)
        {
          const double a_P = diag[c] / alpha; // the relaxed diagonal of the x equation
          D[c] = mesh.cell_volume[c] / a_P;
          // SIMPLEC: V/(a_P - sum a_nb); the boundary and relaxation terms keep it positive
          const double denominator = a_P - off_sum[c];
          D_simplec[c] = denominator > 1e-12 * a_P ? mesh.cell_volume[c] / denominator : D[c];
        }
    return residual;
  }

  void SimplecSolver::Implementation::solve_momentum(SparseMatrix &A, Eigen::VectorXd &b, std::vector<double> &phi,
                                                     Eigen::UmfPackLU<SparseMatrix> &direct, bool first)
  {
    const std::size_t n = mesh.n_cells();
    Eigen::Map<Eigen::VectorXd> x(phi.data(), n);
    if (settings.momentum_solver == FlowSolverParameters::MomentumSolver::direct)
      {
        if (first)
          direct.analyzePattern(A); // symbolic analysis once per mesh
        direct.factorize(A);
        if (direct.info() != Eigen::Success)
          throw std::runtime_error("UMFPACK could not factorise the momentum matrix");
        x = direct.solve(b);
        if (direct.info() != Eigen::Success)
          throw std::runtime_error("UMFPACK momentum solve failed");
        return;
      }
    solve_iteratively(A, b, phi, "momentum");
  }

  void SimplecSolver::Implementation::solve_iteratively(SparseMatrix &A, Eigen::VectorXd &b, std::vector<double> &phi,
                                                        const char *equation)
  {
    // BiCGSTAB on the correction, so that its tolerance is relative to the current residual
    Eigen::Map<Eigen::VectorXd> x(phi.data(), mesh.n_cells());
    const Eigen::VectorXd r = b - A * x;
    if (r.norm() == 0)
      return;
    auto run = [&](auto &solver) {
      solver.setTolerance(settings.linear_solver_tolerance);
      solver.setMaxIterations(1000);
      solver.compute(A);
      const Eigen::VectorXd dx = solver.solve(r);
      if (solver.info() != Eigen::Success)
        throw std::runtime_error(std::string("BiCGSTAB did not converge on the ") + equation + " equation (" +
                                 std::to_string(solver.iterations()) + " iterations, relative residual " +
                                 format_number(solver.error()) + ")");
      x += dx;
    };
    switch (settings.momentum_solver)
      {
        case FlowSolverParameters::MomentumSolver::bicgstab_ilu:
          iterative_ilu.preconditioner().setDroptol(1e-4);
          iterative_ilu.preconditioner().setFillfactor(10);
          run(iterative_ilu);
          break;
        case FlowSolverParameters::MomentumSolver::bicgstab_gauss_seidel: run(iterative_gauss_seidel); break;
        default: run(iterative_jacobi); // also k and epsilon with the direct momentum solver
      }
  }

  std::vector<double> SimplecSolver::Implementation::rhie_chow_fluxes() const
  {
    const double rho = fluid.density;
    std::vector<double> F(mesh.n_faces(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const unsigned int P = mesh.owner[f];
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f];
        if (mesh.neighbour[f] >= 0)
          {
            const unsigned int N = mesh.neighbour[f];
            const double w = mesh.face_weight(f);
            const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
            const Vector2 u_f(w * u[P] + (1 - w) * u[N], w * v[P] + (1 - w) * v[N]);
            const Vector2 grad_f = w * grad_p[P] + (1 - w) * grad_p[N];
            const double D_f = w * D[P] + (1 - w) * D[N];
            // u_f = mean(u) - D_f (grad p compact - mean(grad p)) along the face normal
            F[f] = rho * (u_f.dot(nrm) * area - D_f * ((p[N] - p[P]) - grad_f.dot(d)) * area / nrm.dot(d));
          }
        else
          switch (face_kind[f])
            {
              case Kind::velocity_inlet: F[f] = flux[f]; break;
              case Kind::pressure_outlet:
              case Kind::total_pressure_inlet:
                {
                  const Vector2 d = mesh.face_center[f] - mesh.cell_center[P];
                  const Vector2 uP(u[P], v[P]);
                  F[f] = rho * (uP.dot(nrm) * area - D[P] * ((p_b[f] - p[P]) - grad_p[P].dot(d)) * area / nrm.dot(d));
                  break;
                }
              default: F[f] = 0; // walls, axis, symmetry
            }
      }
    return F;
  }

  /// Solves the SIMPLEC pressure correction for the fluxes F*, corrects fluxes, velocities and
  /// pressure; returns the sum over cells of |mass imbalance of F*|.
  double SimplecSolver::Implementation::pressure_correction(std::vector<double> &F)
  {
    const std::size_t n = mesh.n_cells();
    const double rho = fluid.density;
    double *value = matrix_p.valuePtr();
    std::fill(value, value + matrix_p.nonZeros(), 0.0);
    std::vector<double> diag(n, 0.0), imbalance(n, 0.0), coefficient(mesh.n_faces(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const unsigned int P = mesh.owner[f];
        // the mixture's mass balance: liquid cells carry the mixture density ratio of the upwind
        // cell through each face (1 without cavitation); it weights flux and correction alike, so
        // the matrix stays symmetric
        const double m = face_mixture_ratio(f, F[f]);
        imbalance[P] += m * F[f];
        const Vector2 &nrm = mesh.face_normal[f];
        if (mesh.neighbour[f] >= 0)
          {
            const unsigned int N = mesh.neighbour[f];
            imbalance[N] -= m * F[f];
            const double w = mesh.face_weight(f);
            const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
            coefficient[f] = rho * (w * D_simplec[P] + (1 - w) * D_simplec[N]) * mesh.face_area[f] / nrm.dot(d);
            value[owner_row_index[f]] = value[neighbour_row_index[f]] = -m * coefficient[f];
            diag[P] += m * coefficient[f], diag[N] += m * coefficient[f];
          }
        else if (is_pressure_boundary(face_kind[f]))
          {
            coefficient[f] = rho * D_simplec[P] * mesh.face_area[f] / distance_to_face(f); // p' = 0 there
            if (F[f] < 0)
              {
                // p_b = p_0 - F^2/(2 rho A^2) moves with the inflow: p_b' = -|F| F'/(rho A^2), so
                // F' = c (p_P' - p_b') gives F' = c p_P'/(1 + c |F|/(rho A^2)). Without it the
                // boundary pressure lags the flux and the iteration oscillates and diverges.
                const double A = mesh.face_area[f];
                coefficient[f] /= 1 + coefficient[f] * std::abs(F[f]) / (rho * A * A);
              }
            diag[P] += m * coefficient[f];
          }
      }
    if (!has_pressure_boundary)
      diag[0] *= 2; // a closed domain: tie p' of one cell to zero (p' is defined up to a constant)
    for (std::size_t c = 0; c < n; ++c)
      value[diagonal_index[c]] = diag[c];
    Eigen::VectorXd rhs(n);
    double sum = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        rhs[c] = -imbalance[c];
        if (!cavitation || !cavitating[c])
          sum += std::abs(imbalance[c]);
      }
    if (cavitation)
      {
        // a cavitating cell holds p = p_cav: its row is p' = p_cav - p, and its liquid neighbours
        // see that p' as known (moved to their right-hand side, symmetric elimination); the
        // liquid fraction balances its mass instead (update_liquid_fraction)
        for (std::size_t f = 0; f < mesh.n_faces(); ++f)
          if (mesh.neighbour[f] >= 0)
            {
              const unsigned int P = mesh.owner[f], N = mesh.neighbour[f];
              if (!cavitating[P] && !cavitating[N])
                continue;
              const double a = -value[owner_row_index[f]]; // m c
              if (!cavitating[P])
                rhs[P] += a * (cavitation_pressure - p[N]);
              if (!cavitating[N])
                rhs[N] += a * (cavitation_pressure - p[P]);
              value[owner_row_index[f]] = value[neighbour_row_index[f]] = 0;
            }
        for (std::size_t c = 0; c < n; ++c)
          if (cavitating[c])
            {
              value[diagonal_index[c]] = 1;
              rhs[c] = cavitation_pressure - p[c];
            }
      }
    // Conjugate gradients preconditioned by the Cholesky factor of a recent matrix: a new numeric
    // factorisation (the symbolic one is reused) when the factor has aged so that CG needs more than
    // a few steps. The tight tolerance keeps the corrected fluxes conservative to round-off.
    auto refactorize = [&] {
      pressure_factor.factorize(matrix_p);
      if (pressure_factor.info() != Eigen::Success)
        throw std::runtime_error("CHOLMOD could not factorise the pressure-correction matrix");
      have_pressure_factor = true;
    };
    bool fresh = !have_pressure_factor || last_cg_iterations > 6;
    if (fresh)
      refactorize();
    pressure_cg.setTolerance(1e-12);
    pressure_cg.setMaxIterations(200);
    pressure_cg.compute(matrix_p);
    Eigen::VectorXd pc = pressure_cg.solve(rhs);
    if (pressure_cg.info() != Eigen::Success && !fresh)
      {
        // the matrix has moved too far from the old factor's: renew it and solve again
        refactorize();
        pc = pressure_cg.solve(rhs);
      }
    last_cg_iterations = static_cast<unsigned int>(pressure_cg.iterations());
    if (pressure_cg.info() != Eigen::Success)
      throw std::runtime_error("the pressure-correction solve did not converge (" +
                               std::to_string(last_cg_iterations) + " CG iterations, relative residual " +
                               format_number(pressure_cg.error()) + ")");

    // conservative flux correction
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] >= 0)
        F[f] -= coefficient[f] * (pc[mesh.neighbour[f]] - pc[mesh.owner[f]]);
      else if (is_pressure_boundary(face_kind[f]))
        F[f] += coefficient[f] * pc[mesh.owner[f]];
    // velocity and pressure correction
    std::vector<double> pc_cells(pc.data(), pc.data() + n), pc_b(mesh.n_faces(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] < 0 && !is_pressure_boundary(face_kind[f]))
        pc_b[f] = pc[mesh.owner[f]];
    const std::vector<Vector2> grad_pc = mesh.gradient(pc_cells, pc_b);
    for (std::size_t c = 0; c < n; ++c)
      {
        u[c] -= D_simplec[c] * grad_pc[c].x();
        v[c] -= D_simplec[c] * grad_pc[c].y();
        set_cell_pressure(c, p[c] + pressure_relaxation * pc[c]);
      }
    return sum;
  }

  Residuals SimplecSolver::Implementation::iterate(bool first)
  {
    update_boundary_values();
    mesh.gradient(p, p_b, grad_p);
    Eigen::VectorXd bu, bv;
    double scale_u = 0, scale_v = 0;
    const std::vector<double> u_old = u, v_old = v;
    const double ru = assemble_momentum(matrix_u, bu, u_old, u_b, v_old, 0, scale_u);
    const double rv = assemble_momentum(matrix_v, bv, v_old, v_b, u_old, 1, scale_v);
    if (coupled_iterations)
      {
        double throughput = 0;
        const double imbalance = coupled_step(bu, bv, throughput);
        return finish_iteration(ru, rv, std::max(scale_u, 1e-300), imbalance, throughput);
      }
    solve_momentum(matrix_u, bu, u, direct_u, first);
    solve_momentum(matrix_v, bv, v, direct_v, first);
    update_boundary_values();
    std::vector<double> F = rhie_chow_fluxes();
    const double throughput = throughput_of(F);
    const double imbalance = pressure_correction(F);
    flux = F;
    return finish_iteration(ru, rv, std::max(scale_u, 1e-300), imbalance, throughput);
  }

  Residuals SimplecSolver::Implementation::finish_iteration(double ru, double rv, double scale, double imbalance,
                                                           double throughput)
  {
    if (cavitation)
      {
        update_liquid_fraction();
        update_mass_flux();
      }
    update_inflow_speeds();
    Residuals r;
    if (turbulent)
      {
        turbulence_step(r);
        update_face_viscosity();
      }
    r.u = ru / scale;
    r.v = rv / scale;
    r.continuity = imbalance / std::max(throughput, 1e-300);
    return r;
  }

  /// One coupled iteration: the relaxed momentum equations (assembled, with the pressure gradient
  /// explicit in bu, bv) and continuity of the Rhie-Chow fluxes, solved together for u, v, p.
  ///   momentum:   A u + V G_int(p) = b + V G_int(p_old)   (G_int: the least-squares gradient's
  ///               interior part; its boundary part, with the walls' extrapolated pressure, stays
  ///               explicit in b, so that at convergence the equation is SIMPLEC's exactly)
  ///   continuity: sum_f m_f F_f = 0,  F_f = rho [u_f.S - D_f ((p_N - p_P) - mean(grad p).d) |S|/(n.d)]
  ///               with u_f = w u_P + (1 - w) u_N implicit, the mean gradient of the last pressure
  ///               explicit, and m_f the upwind mixture density ratio of the last fluxes.
  /// Cavitating cells hold p = p_cav in place of their continuity (their liquid fraction balances
  /// their mass, as with SIMPLEC). Returns the mass imbalance of the state the step started from
  /// (its Rhie-Chow fluxes), and in `throughput' their inflow or outflow, whichever is larger.
  double SimplecSolver::Implementation::coupled_step(const Eigen::VectorXd &bu, const Eigen::VectorXd &bv,
                                                     double &throughput)
  {
    const std::size_t n = mesh.n_cells();
    const double rho = fluid.density;
    const std::vector<double> F_now = rhie_chow_fluxes();
    throughput = throughput_of(F_now);
    double sum = 0;
    {
      std::vector<double> imbalance(n, 0.0);
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        {
          const double mF = face_mixture_ratio(f, F_now[f]) * F_now[f];
          imbalance[mesh.owner[f]] += mF;
          if (mesh.neighbour[f] >= 0)
            imbalance[mesh.neighbour[f]] -= mF;
        }
      for (std::size_t c = 0; c < n; ++c)
        if (!cavitation || !cavitating[c])
          sum += std::abs(imbalance[c]);
    }
    // rows whose continuity is replaced by a given pressure: cavitating cells, and in a closed domain
    // (p defined up to a constant; the continuity rows sum to zero) the first cell
    std::vector<char> pinned(n, 0);
    for (std::size_t c = 0; c < n; ++c)
      pinned[c] = cavitation && cavitating[c];
    if (!has_pressure_boundary)
      pinned[0] = 1;

    auto &t = coupled_entries;
    t.clear();
    Eigen::VectorXd rhs(3 * n);
    const std::size_t pressure = 2 * n; // offset of p in the unknowns (u, v, p)
    for (int component = 0; component < 2; ++component)
      {
        const SparseMatrix &A = component == 0 ? matrix_u : matrix_v;
        const std::size_t offset = component * n;
        for (int column = 0; column < A.outerSize(); ++column)
          for (SparseMatrix::InnerIterator it(A, column); it; ++it)
            t.emplace_back(offset + it.row(), offset + it.col(), it.value());
        rhs.segment(offset, n) = component == 0 ? bu : bv;
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
              rhs[component * n + c] += a * (p[other] - p[c]);
            }
        }
    rhs.segment(pressure, n).setZero();
    auto continuity = [&](std::size_t row, std::size_t column, double value) {
      t.emplace_back(pressure + row, column, pinned[row] ? 0.0 : value);
    };
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const unsigned int P = mesh.owner[f];
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f], m = face_mixture_ratio(f, flux[f]);
        const double ax = rho * area * nrm.x(), ay = rho * area * nrm.y();
        if (mesh.neighbour[f] >= 0)
          {
            const unsigned int N = mesh.neighbour[f];
            const double w = mesh.face_weight(f);
            const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
            const double D_f = w * D[P] + (1 - w) * D[N];
            const double c_f = rho * D_f * area / nrm.dot(d);
            const double explicit_part = c_f * (w * grad_p[P] + (1 - w) * grad_p[N]).dot(d);
            for (const auto &[row, sign] : {std::pair<unsigned int, double>{P, m}, {N, -m}})
              {
                continuity(row, P, sign * w * ax), continuity(row, N, sign * (1 - w) * ax);
                continuity(row, n + P, sign * w * ay), continuity(row, n + N, sign * (1 - w) * ay);
                continuity(row, pressure + P, sign * c_f), continuity(row, pressure + N, -sign * c_f);
                rhs[pressure + row] -= sign * explicit_part;
              }
          }
        else if (is_pressure_boundary(face_kind[f]))
          {
            const Vector2 d = mesh.face_center[f] - mesh.cell_center[P];
            const double c_b = rho * D[P] * area / nrm.dot(d);
            continuity(P, P, m * ax), continuity(P, n + P, m * ay), continuity(P, pressure + P, m * c_b);
            rhs[pressure + P] -= m * (-c_b * p_b[f] + c_b * grad_p[P].dot(d));
          }
        else if (face_kind[f] == Kind::velocity_inlet)
          rhs[pressure + P] -= m * flux[f];
      }
    for (std::size_t c = 0; c < n; ++c)
      {
        t.emplace_back(pressure + c, pressure + c, pinned[c] ? 1.0 : 0.0);
        if (pinned[c])
          rhs[pressure + c] = cavitation && cavitating[c] ? cavitation_pressure : p[c];
      }
    if (!coupled_analyzed)
      {
        // once per mesh: the pattern (the entries are the same at every assembly), where each entry
        // goes in the value array, and the LU's symbolic analysis
        matrix_coupled.resize(3 * n, 3 * n);
        matrix_coupled.setFromTriplets(t.begin(), t.end());
        const int *inner = matrix_coupled.innerIndexPtr(), *outer = matrix_coupled.outerIndexPtr();
        coupled_position.resize(t.size());
        for (std::size_t k = 0; k < t.size(); ++k)
          coupled_position[k] = std::lower_bound(inner + outer[t[k].col()], inner + outer[t[k].col() + 1], t[k].row()) - inner;
        coupled_lu.analyzePattern(matrix_coupled);
        coupled_analyzed = true;
      }
    else
      {
        // the values in place (duplicates summed, as setFromTriplets does)
        double *value = matrix_coupled.valuePtr();
        std::fill(value, value + matrix_coupled.nonZeros(), 0.0);
        for (std::size_t k = 0; k < t.size(); ++k)
          value[coupled_position[k]] += t[k].value();
      }
    coupled_lu.factorize(matrix_coupled);
    if (coupled_lu.info() != Eigen::Success)
      throw std::runtime_error("UMFPACK could not factorise the coupled pressure-velocity matrix");
    const Eigen::VectorXd x = coupled_lu.solve(rhs);
    if (coupled_lu.info() != Eigen::Success || !x.allFinite())
      throw std::runtime_error("the coupled pressure-velocity solve failed");
    const std::vector<double> p_old = p;
    for (std::size_t c = 0; c < n; ++c)
      u[c] = x[c], v[c] = x[n + c], p[c] = x[pressure + c];
    // the fluxes of the solution (the lagged mean gradient and boundary pressures as in the system):
    // conservative to the LU's round-off
    flux = rhie_chow_fluxes();
    // a cycle caught by the cycle test relaxes the pressure update by the factor it lowered the
    // pressure relaxation (1 until then: the coupled system needs no relaxation of its own)
    const double beta = pressure_relaxation / settings.pressure_relaxation;
    for (std::size_t c = 0; c < n; ++c)
      set_cell_pressure(c, p_old[c] + beta * (p[c] - p_old[c]));
    return sum;
  }

  void SimplecSolver::Implementation::update_face_viscosity()
  {
    mu_face.resize(mesh.n_faces());
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        const unsigned int P = mesh.owner[f];
        double mut = 0; // at walls the turbulent viscosity vanishes (k = 0)
        if (mesh.neighbour[f] >= 0)
          {
            const double w = mesh.face_weight(f);
            mut = w * mu_t[P] + (1 - w) * mu_t[mesh.neighbour[f]];
          }
        else if (face_kind[f] != Kind::wall)
          mut = mu_t[P];
        mu_face[f] = fluid.viscosity + mut;
      }
  }

  /// The liquid fraction of the cavitating cells from their mixture mass balance with the new
  /// volume fluxes, upwind: gamma~_P sum(out) F = sum(in) gamma~_upwind |F| (Gauss-Seidel sweeps). A
  /// cell whose inflow would need gamma~ >= 1 is liquid again: the cavity closes there and its
  /// pressure is free to rise.
  void SimplecSolver::Implementation::update_liquid_fraction()
  {
    const double ratio = settings.vapour_density_ratio;
    for (int sweep = 0; sweep < 4; ++sweep)
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        {
          if (!cavitating[c])
            continue;
          double in = 0, out = 0;
          for (unsigned int f : mesh.cell_faces[c])
            {
              const double F = mesh.owner[f] == c ? flux[f] : -flux[f]; // out of c
              if (F > 0)
                out += F;
              else if (F < 0)
                in += -F * (mesh.neighbour[f] < 0 ? 1.0 : mixture_ratio(mesh.owner[f] == c ? mesh.neighbour[f] : mesh.owner[f]));
            }
          if (out <= 1e-300 * (in + 1))
            continue; // stagnant: keep
          const double mixture = in / out;
          if (mixture >= 1)
            cavitating[c] = 0, liquid_fraction[c] = 1;
          else
            liquid_fraction[c] = std::max(0.0, (mixture - ratio) / (1 - ratio));
        }
  }

  namespace k_epsilon
  {
    // the standard k-epsilon constants (the paper's model, issue 5)
    constexpr double C_mu = 0.09, C1 = 1.44, C2 = 1.92, sigma_k = 1.0, sigma_epsilon = 1.3;
    /// Launder-Sharma: damping of mu_t, f_mu = exp(-3.4/(1 + Re_t/50)^2)
    inline double f_mu(double Re_t) { return std::exp(-3.4 / std::pow(1 + Re_t / 50, 2)); }
    /// Launder-Sharma: damping of the destruction of epsilon~, f_2 = 1 - 0.3 exp(-Re_t^2)
    inline double f_2(double Re_t) { return 1 - 0.3 * std::exp(-Re_t * Re_t); }

    // Two-layer wall treatment: Wolfshtein's one-equation model with Chen and Patel's constants
    // near walls, blended into the standard model by Jongen and Marx's function of Re_y.
    constexpr double kappa = 0.41;
    const double C_l = kappa * std::pow(C_mu, -0.75); // 2.495
    constexpr double A_mu = 70;                       // length scale of the mu_t damping
    const double A_epsilon = 2 * C_l;                 // gives epsilon -> 2 nu k/y^2 at the wall
    constexpr double Re_y_switch = 60, Re_y_width = 10;
    /// lambda = 1 in the outer (standard k-epsilon) layer, 0 at the wall
    inline double outer_weight(double Re_y)
    {
      return 0.5 * (1 + std::tanh((Re_y - Re_y_switch) / (Re_y_width / std::atanh(0.98))));
    }
  } // namespace k_epsilon

  void SimplecSolver::Implementation::compute_wall_distance()
  {
    // shortest distance from each cell centre to a wall face (segment), by brute force: the
    // valve's meshes have a few thousand wall faces, and it runs once per mesh
    std::vector<std::array<Vector2, 2>> walls;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] < 0 && face_kind[f] == Kind::wall)
        walls.push_back({mesh.points[mesh.face_points[f][0]], mesh.points[mesh.face_points[f][1]]});
    wall_distance.assign(mesh.n_cells(), 1e300);
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const Vector2 &x = mesh.cell_center[c];
        double best = 1e300;
        for (const auto &w : walls)
          {
            const Vector2 t = w[1] - w[0];
            const double s = std::clamp((x - w[0]).dot(t) / t.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (x - w[0] - s * t).squaredNorm());
          }
        wall_distance[c] = std::sqrt(best);
      }
  }

  /// One step of the k and epsilon equations, with the fluxes and velocities of this iteration:
  ///   div(rho u k) = div((mu + mu_t/sigma_k) grad k) + P - rho epsilon [- D]
  ///   div(rho u e) = div((mu + mu_t/sigma_e) grad e) + C1 e/k P - C2 [f_2] rho e^2/k [+ E]
  ///   P = mu_t G,  G = 2 (u_x^2 + v_r^2 [+ (v/r)^2]) + (u_r + v_x)^2.
  /// Two-layer (the default): mu_t = lambda rho C_mu k^2/e + (1 - lambda) rho C_mu sqrt(k) l_mu and
  /// e = k^(3/2)/l_e imposed with the weight 1 - lambda, l = C_l y (1 - exp(-Re_y/A)),
  /// Re_y = sqrt(k) y/nu, lambda(Re_y) from 0 at the wall to 1 beyond Re_y = 60.
  /// Launder-Sharma: e is e~, mu_t = rho C_mu f_mu k^2/e~, D = 2 mu |grad sqrt k|^2,
  /// E = 2 mu nu_t |grad grad u|^2, Re_t = rho k^2/(mu e~).
  /// Walls: k = 0 (and e~ = 0). An inflow brings k = 3/2 (I u_n)^2, epsilon = C_mu^(3/4) k^(3/2)/L;
  /// an outflow, the axis and a symmetry plane take the cell's values. The sinks are implicit.
  void SimplecSolver::Implementation::turbulence_step(Residuals &r)
  {
    using namespace k_epsilon;
    const std::size_t n = mesh.n_cells(), nf = mesh.n_faces();
    const double rho = fluid.density, mu = fluid.viscosity, alpha = settings.turbulence_relaxation;
    const bool axisymmetric = mesh.geometry == Geometry::axisymmetric;
    const bool launder_sharma = settings.turbulence == FlowSolverParameters::Turbulence::k_epsilon_launder_sharma;

    // boundary values
    double k_inflow = 0, epsilon_inflow = 0;
    for (std::size_t f = 0; f < nf; ++f)
      {
        if (mesh.neighbour[f] >= 0)
          continue;
        const unsigned int P = mesh.owner[f];
        const BoundaryCondition &bc = patch_condition[mesh.face_patch[f]];
        if (face_kind[f] == Kind::wall)
          {
            k_b[f] = 0;
            // e~ = 0 at the wall (Launder-Sharma); the two-layer model imposes epsilon in the wall
            // cells, so the wall value only closes the gradient
            epsilon_b[f] = launder_sharma ? 0 : epsilon[P];
          }
        else if (flux[f] < 0 && (face_kind[f] == Kind::velocity_inlet || is_pressure_boundary(face_kind[f])))
          {
            const double u_n = -flux[f] / (rho * mesh.face_area[f]);
            k_b[f] = 1.5 * std::pow(bc.turbulence_intensity * u_n, 2);
            epsilon_b[f] = std::pow(C_mu, 0.75) * std::pow(k_b[f], 1.5) / bc.turbulence_length;
            k_inflow = std::max(k_inflow, k_b[f]), epsilon_inflow = std::max(epsilon_inflow, epsilon_b[f]);
          }
        else
          k_b[f] = k[P], epsilon_b[f] = epsilon[P];
      }
    // A start from nothing (or from a laminar solution): turbulence of 5 % intensity of the local
    // flow speed, at least the inflow's, with the inflow's length scale. Low-Reynolds and two-layer
    // models have a laminar branch (k = 0 solves them), so a seed as weak as a slow plenum's inflow
    // would never grow where the real flow is turbulent; a strong seed decays where it is not.
    if (*std::max_element(k.begin(), k.end()) <= 0)
      {
        const double L = patch_condition[0].turbulence_length;
        double k_start_max = 0, epsilon_start_max = 0;
        for (std::size_t c = 0; c < n; ++c)
          {
            k[c] = std::max(k_inflow, 1.5 * std::pow(0.05 * std::hypot(u[c], v[c]), 2));
            epsilon[c] = std::max(epsilon_inflow, std::pow(C_mu, 0.75) * std::pow(k[c], 1.5) / L);
            k_start_max = std::max(k_start_max, k[c]), epsilon_start_max = std::max(epsilon_start_max, epsilon[c]);
          }
        if (k_inflow <= 0)
          k_inflow = k_start_max, epsilon_inflow = epsilon_start_max;
      }
    const double k_floor = 1e-12 * std::max(k_inflow, *std::max_element(k.begin(), k.end()));
    const double epsilon_floor = 1e-12 * std::max(epsilon_inflow, *std::max_element(epsilon.begin(), epsilon.end()));

    // velocity gradients and production
    const std::vector<Vector2> gu = mesh.gradient(u, u_b), gv = mesh.gradient(v, v_b);
    std::vector<double> production(n), strain(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        double G = 2 * (gu[c].x() * gu[c].x() + gv[c].y() * gv[c].y()) + std::pow(gu[c].y() + gv[c].x(), 2);
        if (axisymmetric)
          G += 2 * std::pow(v[c] / mesh.cell_center[c].y(), 2);
        production[c] = mu_t[c] * G;
        strain[c] = std::sqrt(0.5 * G); // |S| = sqrt(S_ij S_ij)
      }
    // Launder-Sharma's low-Reynolds terms D and E; the two-layer model's wall-layer epsilon and weight
    std::vector<double> low_re_D(n, 0.0), low_re_E(n, 0.0), Re_t(n, 0.0), layer_epsilon(n, 0.0),
      layer_weight(n, 0.0);
    if (launder_sharma)
      {
        std::vector<double> sqrt_k(n), sqrt_k_b(nf, 0.0);
        for (std::size_t c = 0; c < n; ++c)
          sqrt_k[c] = std::sqrt(std::max(k[c], 0.0));
        for (std::size_t f = 0; f < nf; ++f)
          if (mesh.neighbour[f] < 0)
            sqrt_k_b[f] = std::sqrt(std::max(k_b[f], 0.0));
        const std::vector<Vector2> g_sqrt_k = mesh.gradient(sqrt_k, sqrt_k_b);
        // second derivatives: gradients of the four velocity-gradient components (zero-gradient at the boundary)
        std::vector<double> second(n, 0.0);
        std::vector<double> component(n), component_b(nf, 0.0);
        for (int j = 0; j < 4; ++j)
          {
            for (std::size_t c = 0; c < n; ++c)
              component[c] = j < 2 ? gu[c][j] : gv[c][j - 2];
            for (std::size_t f = 0; f < nf; ++f)
              if (mesh.neighbour[f] < 0)
                component_b[f] = component[mesh.owner[f]];
            const std::vector<Vector2> g = mesh.gradient(component, component_b);
            for (std::size_t c = 0; c < n; ++c)
              second[c] += g[c].squaredNorm();
          }
        for (std::size_t c = 0; c < n; ++c)
          {
            low_re_D[c] = 2 * mu * g_sqrt_k[c].squaredNorm();
            low_re_E[c] = 2 * mu * (mu_t[c] / rho) * second[c];
            Re_t[c] = rho * k[c] * k[c] / (mu * std::max(epsilon[c], epsilon_floor));
          }
      }
    else
      for (std::size_t c = 0; c < n; ++c)
        {
          const double kc = std::max(k[c], k_floor), y = wall_distance[c];
          const double Re_y = rho * std::sqrt(kc) * y / mu;
          const double l_epsilon = C_l * y * (1 - std::exp(-Re_y / A_epsilon));
          layer_epsilon[c] = std::pow(kc, 1.5) / std::max(l_epsilon, 1e-300);
          layer_weight[c] = 1 - outer_weight(Re_y);
        }

    // face diffusivities mu + mu_t/sigma
    std::vector<double> gamma(nf);
    auto diffusivity = [&](double sigma) {
      for (std::size_t f = 0; f < nf; ++f)
        gamma[f] = mu + (mu_face[f] - mu) / sigma;
    };
    double scale = 0;
    Eigen::VectorXd b;
    // residuals relative to the level of k and e the inflow brings (or the largest), not to the
    // local values: where turbulence decays towards laminar flow, those vanish and a relative
    // residual would never fall
    const double k_level = std::max(k_inflow, 1e-6 * *std::max_element(k.begin(), k.end()));
    const double epsilon_level = std::max(epsilon_inflow, 1e-6 * *std::max_element(epsilon.begin(), epsilon.end()));
    std::vector<double> level(n);

    // k: the dissipation rho e (+ D) as an implicit sink rho e/k k
    diffusivity(sigma_k);
    assemble_transport(matrix_k, b, k, k_b, gamma);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c], kc = std::max(k[c], k_floor);
        const double e = launder_sharma ? std::max(epsilon[c], 0.0) :
                                          layer_weight[c] * layer_epsilon[c] + (1 - layer_weight[c]) * std::max(epsilon[c], 0.0);
        diag[c] += (rho * e + low_re_D[c]) / kc * V;
        b[c] += production[c] * V;
      }
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(k[c], k_level);
    r.k = relax(matrix_k, b, k, alpha, level, scale);
    r.k /= std::max(scale, 1e-300);
    solve_iteratively(matrix_k, b, k, "k");

    // epsilon
    diffusivity(sigma_epsilon);
    assemble_transport(matrix_epsilon, b, epsilon, epsilon_b, gamma);
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c], kc = std::max(k[c], k_floor);
        const double ratio = std::max(epsilon[c], 0.0) / kc;
        diag[c] += C2 * (launder_sharma ? f_2(Re_t[c]) : 1.0) * rho * ratio * V;
        b[c] += (C1 * ratio * production[c] + low_re_E[c]) * V;
      }
    if (!launder_sharma)
      {
        // the wall layer: each row becomes (1 - w)(transport) + w a_P (e - e_layer), so that epsilon
        // is the one-equation model's where w = 1 and the transport equation's where w = 0
        const int *inner = matrix_epsilon.innerIndexPtr(), *outer = matrix_epsilon.outerIndexPtr();
        double *value = matrix_epsilon.valuePtr();
        for (std::size_t column = 0; column < n; ++column)
          for (int j = outer[column]; j < outer[column + 1]; ++j)
            if (static_cast<std::size_t>(inner[j]) != column)
              value[j] *= 1 - layer_weight[inner[j]];
        for (std::size_t c = 0; c < n; ++c)
          {
            const double w = layer_weight[c];
            b[c] = (1 - w) * b[c] + w * diag[c] * layer_epsilon[c];
            // keeps sum |a_nb| <= a_P (diagonal dominance) for any w
          }
      }
    for (std::size_t c = 0; c < n; ++c)
      level[c] = std::max(epsilon[c], epsilon_level);
    r.epsilon = relax(matrix_epsilon, b, epsilon, alpha, level, scale);
    r.epsilon /= std::max(scale, 1e-300);
    solve_iteratively(matrix_epsilon, b, epsilon, "epsilon");

    // bounded, then the turbulent viscosity (relaxed, at most the limit)
    const double mu_t_limit = viscosity_ratio_limit * mu;
    cells_at_viscosity_limit = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        k[c] = std::max(k[c], k_floor);
        epsilon[c] = std::max(epsilon[c], epsilon_floor);
        double target;
        if (launder_sharma)
          target = rho * C_mu * f_mu(rho * k[c] * k[c] / (mu * epsilon[c])) * k[c] * k[c] / epsilon[c];
        else
          {
            const double y = wall_distance[c], Re_y = rho * std::sqrt(k[c]) * y / mu;
            const double l_mu = C_l * y * (1 - std::exp(-Re_y / A_mu));
            const double lambda = outer_weight(Re_y);
            // Durbin's realizability bound on the time scale, T <= alpha/(sqrt 6 C_mu |S|), alpha = 0.6:
            // the normal stresses of the Boussinesq form stay >= 0 where the strain is strong (the
            // orifice's entry, the jet's stagnation on the flapper), which the standard model violates
            double time_scale = k[c] / epsilon[c];
            if (settings.realizability_coefficient > 0)
              time_scale = std::min(time_scale, settings.realizability_coefficient / (std::sqrt(6.0) * C_mu * std::max(strain[c], 1e-300)));
            target = lambda * rho * C_mu * k[c] * time_scale + (1 - lambda) * rho * C_mu * std::sqrt(k[c]) * l_mu;
          }
        cells_at_viscosity_limit += target > mu_t_limit;
        mu_t[c] += settings.turbulent_viscosity_relaxation * (std::min(target, mu_t_limit) - mu_t[c]);
      }
  }

  std::vector<std::vector<double> *> SimplecSolver::Implementation::accelerated_fields()
  {
    std::vector<std::vector<double> *> fields{&u, &v, &p, &flux};
    if (turbulent)
      fields.insert(fields.end(), {&k, &epsilon, &mu_t});
    if (cavitation)
      fields.push_back(&liquid_fraction);
    return fields;
  }

  Eigen::VectorXd SimplecSolver::Implementation::pack_state()
  {
    const auto fields = accelerated_fields();
    if (field_scales.size() != fields.size())
      {
        field_scales.clear();
        for (const auto *field : fields)
          {
            double largest = 0;
            for (double value : *field)
              largest = std::max(largest, std::abs(value));
            field_scales.push_back(largest > 0 ? largest : 1.0);
          }
      }
    std::size_t size = 0;
    for (const auto *field : fields)
      size += field->size();
    Eigen::VectorXd x(size);
    std::size_t at = 0;
    for (std::size_t j = 0; j < fields.size(); ++j)
      for (double value : *fields[j])
        x[at++] = value / field_scales[j];
    return x;
  }

  /// Writes an accelerated state back, bounded (k, epsilon > 0, mu_t >= 0, 0 <= gamma <= 1), with
  /// what depends on it (mass fluxes, face viscosities, pressure boundaries' inflow speeds).
  void SimplecSolver::Implementation::unpack_state(const Eigen::VectorXd &x)
  {
    const auto fields = accelerated_fields();
    std::vector<double> k_before, epsilon_before;
    if (turbulent)
      k_before = k, epsilon_before = epsilon;
    std::size_t at = 0;
    for (std::size_t j = 0; j < fields.size(); ++j)
      for (double &value : *fields[j])
        value = x[at++] * field_scales[j];
    if (turbulent)
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        {
          // a combination may overshoot below zero where k or epsilon is small: keep the positive
          // value it came from, scaled down at most tenfold
          k[c] = std::max(k[c], 0.1 * k_before[c]);
          epsilon[c] = std::max(epsilon[c], 0.1 * epsilon_before[c]);
          mu_t[c] = std::max(mu_t[c], 0.0);
        }
    if (cavitation)
      {
        for (double &gamma : liquid_fraction)
          gamma = std::clamp(gamma, 0.0, 1.0);
        update_mass_flux();
      }
    if (turbulent)
      update_face_viscosity();
    update_inflow_speeds();
  }

  // ---- public interface ----------------------------------------------------------------------

  SimplecSolver::SimplecSolver(const FvMesh &mesh, const FluidProperties &fluid,
                               const std::map<std::string, BoundaryCondition> &boundaries,
                               const FlowSolverParameters &settings)
    : impl(std::make_unique<Implementation>(mesh, fluid, boundaries, settings))
  {}

  SimplecSolver::~SimplecSolver() = default;

  SolveReport SimplecSolver::solve() { return solve_to(impl->settings.tolerance, true); }

  SolveReport SimplecSolver::solve_to(double tolerance, bool consult_monitor)
  {
    auto &d = *impl;
    SolveReport report;
    std::vector<std::vector<double>> history; // the monitored quantities of the last window + 1 iterations
    auto monitors_settled = [&] {
      if (!d.monitor || !consult_monitor)
        return true;
      history.push_back(d.monitor());
      if (history.size() > d.monitor_window + 1)
        history.erase(history.begin());
      if (history.size() < d.monitor_window + 1)
        return false;
      const auto &now = history.back();
      for (const auto &then : history)
        for (std::size_t j = 0; j < now.size(); ++j)
          if (std::abs(then[j] - now[j]) > d.monitor_change * std::abs(now[j]))
            return false;
      return true;
    };
    // the stall test: the smallest of the largest scaled residual in this window and the last
    double window_best = std::numeric_limits<double>::infinity(), previous_window_best = window_best;
    // the same on the shorter cycle window, which lowers the pressure relaxation
    double cycle_best = window_best, previous_cycle_best = window_best;
    d.pressure_relaxation = d.settings.pressure_relaxation;
    d.coupled_iterations = d.settings.coupling == FlowSolverParameters::Coupling::coupled;
    std::unique_ptr<AndersonAcceleration> anderson;
    if (d.settings.acceleration_depth > 0)
      anderson = std::make_unique<AndersonAcceleration>(d.settings.acceleration_depth);
    Eigen::VectorXd accelerated_start; // the state the last iteration started from (with acceleration)
    unsigned int stall_test_from = 0;   // the iteration of a switch to coupled iterations (0: none)
    double smallest_change = std::numeric_limits<double>::infinity();
    // leaves the accelerated phase: the history, its start and the field scales are forgotten
    auto stop_acceleration = [&] {
      anderson->restart(), accelerated_start.resize(0), d.field_scales.clear();
      smallest_change = std::numeric_limits<double>::infinity();
    };
    for (unsigned int it = 1;; ++it)
      {
        Residuals r;
        try
          {
            r = d.iterate(it == 1);
          }
        catch (const std::runtime_error &e) // a linear solve failed: the iteration is diverging
          {
            if (!failure_output.empty())
              write_vtu(failure_output);
            throw std::runtime_error("flow: " + d.mesh.source + ": the solution diverged at iteration " +
                                     std::to_string(it) + " (" + e.what() + ")" +
                                     (failure_output.empty() ? "" : "; fields in " + failure_output));
          }
        report.iterations = it;
        report.residuals = r;
        const bool bad = !std::isfinite(r.u) || !std::isfinite(r.v) || !std::isfinite(r.continuity) ||
                         !std::isfinite(r.k) || !std::isfinite(r.epsilon) ||
                         (it > 10 && (r.u > 1e8 || r.continuity > 1e8));
        if (bad)
          {
            if (!failure_output.empty())
              write_vtu(failure_output);
            throw std::runtime_error("flow: " + d.mesh.source + ": the solution diverged at iteration " +
                                     std::to_string(it) + " (residuals u " + format_number(r.u) + ", v " +
                                     format_number(r.v) + ", continuity " + format_number(r.continuity) + ")" +
                                     (failure_output.empty() ? "" : "; fields in " + failure_output));
          }
        if (d.settings.report_interval > 0 && it % d.settings.report_interval == 0)
          {
            if (d.cavitation)
              std::fprintf(stderr, "  iteration %u: %td cavitating cells\n", it,
                           std::count(d.cavitating.begin(), d.cavitating.end(), 1));
            if (d.turbulent)
              std::fprintf(stderr,
                           "  iteration %u: residuals u %.3e, v %.3e, continuity %.3e, k %.3e, epsilon %.3e; max mu_t/mu %.3g\n",
                           it, r.u, r.v, r.continuity, r.k, r.epsilon,
                           *std::max_element(d.mu_t.begin(), d.mu_t.end()) / d.fluid.viscosity);
            else
              std::fprintf(stderr, "  iteration %u: residuals u %.3e, v %.3e, continuity %.3e\n", it, r.u, r.v,
                           r.continuity);
          }
        const bool settled = monitors_settled(); // every iteration, to keep the history
        if (r.u < tolerance && r.v < tolerance && r.continuity < tolerance && r.k < tolerance && r.epsilon < tolerance &&
            settled)
          break;
        if (anderson)
          {
            const double largest = std::max({r.u, r.v, r.continuity, r.k, r.epsilon});
            if (largest < d.settings.acceleration_start)
              {
                const Eigen::VectorXd g = d.pack_state();
                if (accelerated_start.size() == g.size())
                  {
                    const Eigen::VectorXd next = anderson->next(accelerated_start, g);
                    // a combination that made the change grow tenfold has left the region where the
                    // iteration is nearly linear: start the history again from plain SIMPLEC
                    smallest_change = std::min(smallest_change, anderson->change_norm());
                    if (anderson->change_norm() > 10 * smallest_change)
                      anderson->restart(), smallest_change = std::numeric_limits<double>::infinity(),
                                           accelerated_start = g;
                    else // the history keeps the unbounded combination even where unpack_state
                         // clipped k, epsilon or gamma: recording the clipped state instead (the
                         // textbook x_k) cost 8 % more iterations at RV-1's null, same answer
                      d.unpack_state(next), accelerated_start = next;
                  }
                else
                  accelerated_start = g;
              }
            else if (accelerated_start.size() > 0)
              stop_acceleration();
          }
        // A segregated iteration can settle into a limit cycle instead of converging: around a
        // cavity, the cells at its edge switch between liquid and vapour every few iterations, and
        // with them the whole pressure field swings (RV-1's fixed orifice at 20.6 MPa and 60 degC: six
        // cells, period 12, continuity stuck at 1.4e-2 with alpha_p = 0.7; about 500 iterations
        // with 0.5). A smaller pressure relaxation damps the swing; the fixed point does not depend
        // on it (the correction vanishes there), so lowering it changes the path only. Steps of 0.7;
        // the floor 0.3 is a choice, not a measurement: it keeps a run that is merely slow from
        // being slowed further (the cycles seen so far needed one step, to 0.49).
        if (const unsigned int cycle = d.settings.cycle_window; cycle > 0)
          {
            cycle_best = std::min(cycle_best, std::max({r.u, r.v, r.continuity, r.k, r.epsilon}));
            if (it % cycle == 0)
              {
                constexpr double lowest_pressure_relaxation = 0.3;
                if (cycle_best > 0.5 * previous_cycle_best && d.pressure_relaxation > lowest_pressure_relaxation)
                  {
                    d.pressure_relaxation = std::max(lowest_pressure_relaxation, 0.7 * d.pressure_relaxation);
                    if (anderson) // another iteration map: the old history does not belong to it
                      stop_acceleration();
                    if (d.settings.report_interval > 0)
                      std::fprintf(stderr, "  iteration %u: a cycle; pressure relaxation lowered to %.3g\n", it,
                                   d.pressure_relaxation);
                    cycle_best = std::numeric_limits<double>::infinity(); // judge the new setting afresh
                  }
                previous_cycle_best = cycle_best;
                cycle_best = std::numeric_limits<double>::infinity();
              }
          }
        report.pressure_relaxation = d.pressure_relaxation;
        // after a switch from SIMPLEC the coupled iterations are judged on the cycle window: they
        // have no segregation cycle to wait out (in the default sweep, the stalls they resolved took 87-215 of them)
        const unsigned int window = stall_test_from > 0 && d.settings.cycle_window > 0 ? d.settings.cycle_window :
                                                                                        d.settings.stall_window;
        bool stalled = false;
        if (window > 0)
          {
            window_best = std::min(window_best, std::max({r.u, r.v, r.continuity, r.k, r.epsilon}));
            if ((it - stall_test_from) % window == 0)
              {
                stalled = window_best > 0.5 * previous_window_best;
                previous_window_best = window_best;
                window_best = std::numeric_limits<double>::infinity();
              }
          }
        if (stalled && !d.coupled_iterations && d.settings.coupling == FlowSolverParameters::Coupling::simplec_then_coupled)
          {
            // SIMPLEC is caught in a cycle of its segregation: go on coupled from here, with the
            // pressure relaxation the setting's again. The stall test goes on against SIMPLEC's last
            // window: coupled iterations that have not halved its best residual within their first
            // window do not resolve this stall either
            d.coupled_iterations = true;
            d.pressure_relaxation = d.settings.pressure_relaxation;
            if (anderson)
              stop_acceleration();
            window_best = cycle_best = previous_cycle_best = std::numeric_limits<double>::infinity();
            if (d.settings.report_interval > 0)
              std::fprintf(stderr, "  iteration %u: SIMPLEC stalled; coupled iterations from here\n", it);
            stalled = false;
            stall_test_from = it;
          }
        if (it >= d.settings.max_iterations || stalled)
          {
            if (!failure_output.empty())
              write_vtu(failure_output);
            throw NotConverged("flow: " + d.mesh.source + ": not converged in " + std::to_string(it) +
                               (stalled ? " iterations: stalled (residuals u " : " iterations (residuals u ") + format_number(r.u) + ", v " + format_number(r.v) +
                                     (d.turbulent ? ", k " + format_number(r.k) + ", epsilon " + format_number(r.epsilon) : "") +
                                     ", continuity " + format_number(r.continuity) + "; tolerance " +
                                     format_number(tolerance) + (settled ? "" : "; monitored quantities still changing") +
                                     (stall_test_from > 0 ? "; coupled iterations since SIMPLEC stalled at iteration " +
                                                              std::to_string(stall_test_from) :
                                                            "") +
                                     ")");
          }
      }
    d.update_boundary_values();
    d.grad_p = d.mesh.gradient(d.p, d.p_b);
    d.update_boundary_values();
    report.cells_at_viscosity_limit = d.turbulent ? d.cells_at_viscosity_limit : 0;
    return report;
  }

  void SimplecSolver::set_boundary_pressure(const std::string &patch, double pressure)
  {
    const int k = impl->mesh.patch_index(patch);
    if (k < 0 || !is_pressure_boundary(impl->patch_condition[k].kind))
      throw std::invalid_argument("flow: " + impl->mesh.source + ": `" + patch + "' is not a pressure boundary");
    impl->patch_condition[k].pressure = pressure;
    impl->update_boundary_values();
  }

  double SimplecSolver::boundary_pressure(const std::string &patch) const
  {
    const int k = impl->mesh.patch_index(patch);
    if (k < 0 || !is_pressure_boundary(impl->patch_condition[k].kind))
      throw std::invalid_argument("flow: " + impl->mesh.source + ": `" + patch + "' is not a pressure boundary");
    return impl->patch_condition[k].pressure;
  }

  void SimplecSolver::scale_pressure_level(double s)
  {
    if (!(s > 0) || !std::isfinite(s))
      throw std::invalid_argument("flow: pressure scaling " + format_number(s) + " must be > 0");
    auto &d = *impl;
    const double root = std::sqrt(s);
    auto scale = [](std::vector<double> &x, double factor) {
      for (double &value : x)
        value *= factor;
    };
    scale(d.p, s), scale(d.p_b, s);
    for (auto &g : d.grad_p)
      g *= s;
    for (auto *field : {&d.u, &d.v, &d.u_b, &d.v_b, &d.flux, &d.inflow_speed, &d.mu_t})
      scale(*field, root);
    scale(d.k, s), scale(d.k_b, s);
    scale(d.epsilon, s * root), scale(d.epsilon_b, s * root);
    for (auto &bc : d.patch_condition)
      bc.pressure *= s;
    d.update_face_viscosity();
    d.update_boundary_values();
  }

  FlowFields SimplecSolver::fields() const
  {
    const auto &d = *impl;
    FlowFields f;
    f.u = d.u, f.v = d.v, f.p = d.p, f.flux = d.flux;
    f.turbulent = d.turbulent;
    if (d.turbulent)
      f.k = d.k, f.epsilon = d.epsilon, f.turbulent_viscosity = d.mu_t;
    f.face_area = d.mesh.face_area;
    f.density = d.fluid.density;
    if (d.cavitation)
      f.liquid_fraction = d.liquid_fraction, f.cavitating = d.cavitating;
    for (std::size_t k = 0; k < d.patch_condition.size(); ++k)
      if (is_pressure_boundary(d.patch_condition[k].kind))
        f.boundary_pressures.emplace_back(d.mesh.patch_names[k], d.patch_condition[k].pressure);
    return f;
  }

  void SimplecSolver::set_fields(const FlowFields &o)
  {
    auto &d = *impl;
    const bool with_fluxes = !o.flux.empty();
    if (o.u.size() != d.mesh.n_cells() || (with_fluxes && o.flux.size() != d.mesh.n_faces()))
      throw std::invalid_argument("flow: " + d.mesh.source + ": cannot start from the fields of a different mesh");
    d.u = o.u, d.v = o.v, d.p = o.p;
    for (const auto &[name, pressure] : o.boundary_pressures)
      {
        const int k = d.mesh.patch_index(name);
        if (k >= 0 && is_pressure_boundary(d.patch_condition[k].kind))
          d.patch_condition[k].pressure = pressure;
      }
    if (d.turbulent)
      {
        if (o.turbulent)
          d.k = o.k, d.epsilon = o.epsilon, d.mu_t = o.turbulent_viscosity;
        else // from laminar fields: the turbulence model seeds itself (turbulence_step)
          std::fill(d.k.begin(), d.k.end(), 0.0), std::fill(d.epsilon.begin(), d.epsilon.end(), 0.0),
            std::fill(d.mu_t.begin(), d.mu_t.end(), 0.0);
        d.update_face_viscosity();
      }
    for (std::size_t f = 0; f < d.mesh.n_faces(); ++f)
      {
        if (d.face_kind[f] == Kind::velocity_inlet && d.mesh.neighbour[f] < 0)
          continue; // fixed by its condition
        if (with_fluxes) // the face fluxes scale with the face areas of this mesh (same topology, other dimensions)
          d.flux[f] = o.flux[f] * d.mesh.face_area[f] / o.face_area[f] * d.fluid.density / o.density;
        else // fields carried from another mesh (transfer_fields): fluxes of the face velocities
          {
            const unsigned int P = d.mesh.owner[f];
            Vector2 u_f(d.u[P], d.v[P]);
            if (d.mesh.neighbour[f] >= 0)
              {
                const unsigned int N = d.mesh.neighbour[f];
                const double w = d.mesh.face_weight(f);
                u_f = w * u_f + (1 - w) * Vector2(d.u[N], d.v[N]);
              }
            else if (!is_pressure_boundary(d.face_kind[f]))
              u_f.setZero(); // walls, axis, symmetry
            d.flux[f] = d.fluid.density * u_f.dot(d.mesh.face_normal[f]) * d.mesh.face_area[f];
          }
      }
    if (o.liquid_fraction.size() == d.mesh.n_cells())
      d.liquid_fraction = o.liquid_fraction, d.cavitating = o.cavitating;
    else
      std::fill(d.liquid_fraction.begin(), d.liquid_fraction.end(), 1.0), std::fill(d.cavitating.begin(), d.cavitating.end(), 0);
    d.update_mass_flux();
    d.update_inflow_speeds();
    d.update_boundary_values();
    d.grad_p = d.mesh.gradient(d.p, d.p_b);
    d.update_boundary_values();
  }

  void SimplecSolver::initialize_from(const SimplecSolver &other) { set_fields(other.fields()); }

  void SimplecSolver::set_turbulent_viscosity_limit(double ratio)
  {
    if (!(ratio > 0))
      throw std::invalid_argument("flow: turbulent viscosity limit " + format_number(ratio) + " must be > 0");
    auto &d = *impl;
    d.viscosity_ratio_limit = ratio;
    if (!d.turbulent)
      return;
    // at once, so that the next iteration's residuals see the change (the relaxed mu_t is not a
    // residual of its own: a converged state would otherwise pass the test before mu_t moved)
    const double limit = ratio * d.fluid.viscosity;
    for (double &mu_t : d.mu_t)
      mu_t = std::min(mu_t, limit);
    d.update_face_viscosity();
  }

  void SimplecSolver::set_cavitation_pressure(double p_cav)
  {
    auto &d = *impl;
    if (!std::isfinite(p_cav))
      throw std::invalid_argument("flow: cavitation pressure " + format_number(p_cav) + " Pa");
    d.cavitation = true;
    d.cavitation_pressure = p_cav;
    d.update_mass_flux();
  }

  std::vector<double> SimplecSolver::liquid_fraction() const { return impl->liquid_fraction; }

  void SimplecSolver::set_convergence_monitor(std::function<std::vector<double>()> monitor, unsigned int window,
                                              double relative_change)
  {
    impl->monitor = std::move(monitor);
    impl->monitor_window = std::max(1u, window);
    impl->monitor_change = relative_change;
  }

  std::vector<double> SimplecSolver::wall_y_plus() const
  {
    const auto &d = *impl;
    std::vector<double> y_plus(d.mesh.n_cells(), 0.0);
    const double rho = d.fluid.density, mu = d.fluid.viscosity;
    for (std::size_t f = 0; f < d.mesh.n_faces(); ++f)
      if (d.mesh.neighbour[f] < 0 && d.face_kind[f] == Kind::wall)
        {
          const unsigned int P = d.mesh.owner[f];
          const Vector2 &n = d.mesh.face_normal[f];
          Vector2 relative = Vector2(d.u[P], d.v[P]) - d.prescribed_velocity[f];
          relative -= relative.dot(n) * n; // tangential
          const double distance = d.distance_to_face(f);
          const double tau = mu * relative.norm() / distance;
          y_plus[P] = std::max(y_plus[P], std::sqrt(tau * rho) * distance / mu);
        }
    return y_plus;
  }

  const std::vector<double> &SimplecSolver::velocity_x() const { return impl->u; }
  const std::vector<double> &SimplecSolver::velocity_y() const { return impl->v; }
  const std::vector<double> &SimplecSolver::pressure() const { return impl->p; }
  const std::vector<double> &SimplecSolver::turbulent_viscosity() const { return impl->mu_t; }
  const std::vector<double> &SimplecSolver::mass_flux() const { return impl->flux; }
  double SimplecSolver::boundary_pressure(std::size_t f) const { return impl->p_b[f]; }
  Vector2 SimplecSolver::boundary_velocity(std::size_t f) const { return Vector2(impl->u_b[f], impl->v_b[f]); }

  namespace
  {
    /// Per radian (axisymmetric) or per unit depth (planar) -> the whole device
    double revolution(const FvMesh &mesh)
    {
      return mesh.geometry == Geometry::axisymmetric ? 2 * units::pi : 1.0;
    }

    const std::vector<unsigned int> &faces_of(const FvMesh &mesh, const std::string &patch)
    {
      const int k = mesh.patch_index(patch);
      if (k < 0)
        throw std::invalid_argument("flow: no boundary `" + patch + "' in " + mesh.source);
      return mesh.patch_faces[k];
    }
  } // namespace

  double SimplecSolver::flow_rate(const std::string &patch) const
  {
    double q = 0;
    for (unsigned int f : faces_of(impl->mesh, patch))
      q += impl->convecting_flux()[f];
    return q / impl->fluid.density * revolution(impl->mesh);
  }

  double SimplecSolver::mean_pressure(const std::string &patch) const
  {
    double sum = 0, area = 0;
    for (unsigned int f : faces_of(impl->mesh, patch))
      {
        sum += impl->p_b[f] * impl->mesh.face_area[f];
        area += impl->mesh.face_area[f];
      }
    return area > 0 ? sum / area : 0.0;
  }

  double SimplecSolver::mean_total_pressure(const std::string &patch) const
  {
    double sum = 0, flow = 0;
    for (unsigned int f : faces_of(impl->mesh, patch))
      {
        const double weight = std::abs(impl->flux[f]);
        sum += weight * (impl->p_b[f] + 0.5 * impl->fluid.density *
                                          (impl->u_b[f] * impl->u_b[f] + impl->v_b[f] * impl->v_b[f]));
        flow += weight;
      }
    return flow > 0 ? sum / flow : mean_pressure(patch);
  }

  double SimplecSolver::minimum_pressure() const
  {
    double lowest = *std::min_element(impl->p.begin(), impl->p.end());
    for (std::size_t f = 0; f < impl->mesh.n_faces(); ++f)
      if (impl->mesh.neighbour[f] < 0)
        lowest = std::min(lowest, impl->p_b[f]);
    return lowest;
  }

  double SimplecSolver::pressure_force(const std::string &patch, const Vector2 &direction, double p_reference) const
  {
    double F = 0;
    for (unsigned int f : faces_of(impl->mesh, patch))
      F += (impl->p_b[f] - p_reference) * impl->mesh.face_normal[f].dot(direction) * impl->mesh.face_area[f];
    return F * revolution(impl->mesh);
  }

  double SimplecSolver::throughput() const
  {
    double inflow = 0;
    for (std::size_t f = 0; f < impl->mesh.n_faces(); ++f)
      if (impl->mesh.neighbour[f] < 0)
        inflow += std::max(0.0, -impl->flux[f]);
    return inflow;
  }

  double SimplecSolver::max_cell_imbalance() const
  {
    const auto &mesh = impl->mesh;
    std::vector<double> imbalance(mesh.n_cells(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        imbalance[mesh.owner[f]] += impl->flux[f];
        if (mesh.neighbour[f] >= 0)
          imbalance[mesh.neighbour[f]] -= impl->flux[f];
      }
    double largest = 0;
    for (double m : imbalance)
      largest = std::max(largest, std::abs(m));
    return largest / std::max(throughput(), 1e-300);
  }

  double SimplecSolver::net_imbalance() const
  {
    double net = 0;
    for (std::size_t f = 0; f < impl->mesh.n_faces(); ++f)
      if (impl->mesh.neighbour[f] < 0)
        net += impl->flux[f];
    return std::abs(net) / std::max(throughput(), 1e-300);
  }

  void SimplecSolver::write_vtu(const std::string &filename) const
  {
    const auto &d = *impl;
    std::vector<std::pair<std::string, std::vector<double>>> extra{{"y_plus", wall_y_plus()}};
    if (d.turbulent)
      extra.insert(extra.end(), {{"k", d.k}, {"epsilon", d.epsilon}, {"turbulent_viscosity", d.mu_t}});
    if (d.cavitation)
      extra.emplace_back("liquid_fraction", d.liquid_fraction);
    write_fv_vtu(filename, d.mesh, d.p, d.u, d.v, d.p_b, d.u_b, d.v_b, extra);
  }
} // namespace servodrift::flow
