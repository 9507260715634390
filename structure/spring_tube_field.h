#pragma once
// Field level of the spring tube (decision D12, model.md 4.3): linear elasticity of the tube as a
// body of revolution under a bending load, by deal.II finite elements on its meridian section (r, z)
// with the displacement's Fourier harmonic n = 1. That is exact for bending of an axisymmetric body
// at the cost of a 2D model.
//
// The displacement, with phi the angle from the bending plane (x = r cos phi):
//   u_r = a(r, z) cos phi,   u_phi = -b(r, z) sin phi,   u_z = c(r, z) cos phi.
// A rigid translation delta along x is a = b = delta, c = 0; a rigid rotation theta about the y axis
// through the point (0, 0, z_top) is a = b = theta (z - z_top), c = -theta r.
//
// The base face is clamped; the top face moves as a rigid body (the armature seat), described by its
// rotation theta and its lateral displacement delta at the centre of the top face. Two solves, one for
// each unit motion, give the 2x2 stiffness of the top from the strain energy; its inverse is the
// compliance (model.md 1.6), and K_a = M/theta_top under a pure moment (V = 0) is 1/C_MM.
#include "common/thermal_laws.h"

#include <array>
#include <memory>
#include <string>

namespace servodrift::structure
{
  struct SpringTubeFieldOptions
  {
    unsigned int element_degree = 2; ///< FE_Q degree of a, b, c
    unsigned int wall_layers = 4;    ///< element layers through the wall (already times the resolution)
    double aspect_ratio = 4;         ///< axial / radial element size [1]
  };

  /// Load on the rigid top, at the centre of the top face: moment about y (bending toward +x) and
  /// force along x.
  struct TopLoad
  {
    double moment = 0; ///< M [N*m]
    double shear = 0;  ///< V [N]
  };

  struct StressPeak
  {
    double von_mises = 0; ///< largest von Mises stress over the body (all angles phi) [Pa]
    double radius = 0;    ///< where [m]
    double height = 0;    ///< where, from the base of the thin section [m]
  };

  using Matrix2 = std::array<std::array<double, 2>, 2>;

  class SpringTubeField
  {
  public:
    /// The tube at one temperature: dimensions (E13) and Young's modulus (E12) already at T.
    /// The thin section runs from z = 0 to z = l; a base flange, if any, lies below z = 0 and a top
    /// collar above z = l (model.md 4.3).
    SpringTubeField(const laws::SpringTubeGeometry &geometry, double youngs_modulus, double poisson_ratio,
                    const SpringTubeFieldOptions &options);
    ~SpringTubeField();
    SpringTubeField(const SpringTubeField &) = delete;
    SpringTubeField &operator=(const SpringTubeField &) = delete;

    /// make_grid, setup_system, assemble_system, and the two unit-motion solves.
    void run();

    /// [[dM/dtheta, dM/ddelta], [dV/dtheta, dV/ddelta]] of the top [N*m/rad, N; N/rad, N/m].
    Matrix2 stiffness() const;
    /// Inverse of the stiffness: [theta, delta] = C [M, V] [rad/(N*m), rad/N; m/(N*m), m/N].
    Matrix2 compliance() const;
    /// K_a = M / theta_top under a pure moment (the top free to move sideways) [N*m/rad].
    double rotational_stiffness() const;

    /// Rotation and lateral displacement of the top under `load' [rad, m].
    std::array<double, 2> top_motion(const TopLoad &load) const;
    /// Largest von Mises stress under `load', over the quadrature points of every cell and every
    /// angle phi, leaving out the points closer than `end_distance' to the planes where the section
    /// changes: the clamped base, the rigid top and the flange or collar junctions. Where a
    /// perfectly clamped or rigid face meets a free surface the elastic stress is singular, so the
    /// peak with end_distance = 0 grows without bound as the mesh is refined; a distance of about one
    /// wall thickness gives the mesh-converged stress beside the ends (the "hot spot" stress).
    StressPeak peak_stress(const TopLoad &load, double end_distance = 0) const;
    /// Axial stress sigma_zz at (r, z) in the bending plane (phi = 0) under `load' [Pa].
    double axial_stress(const TopLoad &load, double radius, double height) const;

    /// The tube revolved into 3D (`segments' around the axis) with the displacement and the von
    /// Mises and axial stresses at the vertices under `load', as a VTU file (ParaView).
    void write_vtu(const std::string &filename, const TopLoad &load, unsigned int segments = 48) const;

    unsigned int n_dofs() const;
    unsigned int n_cells() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };
} // namespace servodrift::structure
