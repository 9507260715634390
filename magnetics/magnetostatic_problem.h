#pragma once
// Planar magnetostatics in the out-of-plane vector potential A_z (model.md 4.1, D10), with a moving
// body: deal.II finite elements (FE_Q of degree 1 or 2), nonlinear iron by Newton with line search,
// linear recoil magnets, coils as current-density regions, A_z = 0 on the outer boundary.
//
// The body moves by mesh morphing with unchanged topology: its vertices move rigidly, the vertices of
// the air around it follow a Laplace extension of that motion, everything else stays. So the sparsity
// pattern, and the symbolic factorisation of the sparse direct solver (CHOLMOD, through Eigen), are
// computed once per mesh and reused for every position and current.
//
// The force (or torque) on the body comes by two methods:
//  - the weighted (volume) Maxwell stress tensor, F = -w_d int_air T_M : grad V dA, with V the
//    virtual velocity of the body extended smoothly into the air (4.1 item 2);
//  - virtual work at constant current, dW'/ds by central differences of the coenergy W' (item 3).
// With V the mesh's own motion the first is the exact derivative of the discrete coenergy, so the
// second checks it (to its difference quotient's error) rather than estimating its discretisation
// error.
#include "magnetics/bh_curve.h"
#include "common/gmsh_mesh.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace servodrift::magnetics
{
  struct Material
  {
    enum class Kind
    {
      air,       ///< mu0
      linear,    ///< mu0 mu_r
      nonlinear, ///< the arctan B-H law
      magnet,    ///< B = mu0 mu_rm H + B_r, linear recoil (E8)
    } kind = Kind::air;
    double relative_permeability = 1;        ///< linear iron; recoil permeability of a magnet
    std::optional<ArctanBHCurve> curve;      ///< nonlinear iron
    std::array<double, 2> remanence{{0, 0}}; ///< magnet B_r [T]
    double current_density = 0;              ///< out-of-plane J per ampere of excitation [A/m^2/A]
    bool moving = false;                     ///< part of the moving body
    bool morphing = false;                   ///< air that deforms with the motion
  };

  struct Motion
  {
    enum class Kind
    {
      rotation,   ///< about `point', counterclockwise positive [rad]
      translation ///< along `direction' (unit vector) [m]
    } kind = Kind::rotation;
    std::array<double, 2> point{{0, 0}};
    std::array<double, 2> direction{{1, 0}};
  };

  struct NewtonStatistics
  {
    unsigned int iterations = 0;
    double initial_residual = 0; ///< ||R(A = 0)||: the scale of the sources
    double start_residual = 0;   ///< ||R|| of the iterate the solve started from
    double final_residual = 0;
  };

  class MagnetostaticProblem
  {
  public:
    /// `depth': out-of-plane depth w_d [m]. Boundary faces with id 1 get A_z = 0. The mesh is
    /// refined `global_refinements' times (each quadrilateral into four: nested meshes, for
    /// convergence studies).
    MagnetostaticProblem(const PlanarMesh &mesh, const std::map<int, Material> &materials, const Motion &motion,
                         unsigned int fe_degree, double depth, unsigned int global_refinements = 0);
    ~MagnetostaticProblem();
    MagnetostaticProblem(const MagnetostaticProblem &) = delete;
    MagnetostaticProblem &operator=(const MagnetostaticProblem &) = delete;

    /// Morphs the mesh to position s (angle [rad] or displacement [m]) from the reference. Throws
    /// std::runtime_error if a cell would be inverted (the motion is too large for the gaps).
    void set_position(double s);
    double position() const;

    /// Solves at excitation current `current' [A] (coil current densities scale with it), starting
    /// from the last solution, or, where the derivatives dA/ds and d2A/ds2 at this current are known
    /// (from virtual work's central differences, else from the parabola through the last solves at
    /// this current), from their prediction at this position. Chord steps on the last factorisation
    /// while each cuts the residual tenfold, else a Newton step with backtracking line search whose
    /// factorisation the next chord steps use, until ||R|| <= tolerance ||R(0)||.
    NewtonStatistics solve(double current, double tolerance = 1e-10, unsigned int max_iterations = 50);

    /// Weighted Maxwell stress tensor: torque [N*m] (rotation) or force [N] (translation) on the body.
    /// V is the mesh's own motion, so this is Coulomb's virtual work: the exact derivative of the
    /// discrete coenergy at fixed potentials, which is its total derivative since the coenergy is
    /// stationary in them.
    double stress_tensor_force() const;
    /// Coenergy W' = w_d int int_0^H B dH' dA [J] of the last solve, as w_d (int J A - int w(B)),
    /// which equals it at the solution and is stationary there: its error is quadratic in the
    /// solution's.
    double coenergy() const;
    /// dW'/ds at constant current by central differences over +-step, the solves there stopped at
    /// 1e3 x the tolerance; position and solution are restored afterwards, and dA/ds and d2A/ds2 are
    /// kept for the next solve at another position.
    double virtual_work_force(double step);

    /// Mean of B along `component' (0: x, 1: y) over the cells of a material [T].
    double mean_flux_density(int material, unsigned int component) const;
    /// Largest |B| over the quadrature points of a material [T].
    double max_flux_density(int material) const;

    /// A_z, B, |B|, H, J, material id as a VTU file (ParaView).
    void write_vtu(const std::string &filename) const;

    unsigned int n_dofs() const;
    unsigned int n_cells() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };
} // namespace servodrift::magnetics
