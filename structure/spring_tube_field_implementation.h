#pragma once
// The private part of the spring tube's field model (structure/spring_tube_field.h), shared by its
// two units: the elasticity solve (spring_tube_field.cc) and the stresses and the VTU of a solution
// (spring_tube_field_output.cc). It holds deal.II types, so only those two include it.
#include "structure/spring_tube_field.h"

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <vector>

namespace servodrift::structure
{
  namespace spring_tube_field
  {
    /// Strain of the n = 1 harmonic displacement (a, b, c) of the header, split into the parts that
    /// vary as cos phi (eps_rr, eps_phiphi, eps_zz, gamma_rz) and as sin phi (gamma_rphi, gamma_zphi).
    /// Cylindrical small strains with u_r = a cos, u_phi = -b sin, u_z = c cos:
    ///   eps_rr = a_r,  eps_phiphi = (a - b)/r,  eps_zz = c_z,  gamma_rz = a_z + c_r,
    ///   gamma_rphi = -(b_r + (a - b)/r),  gamma_zphi = -(b_z + c/r).
    /// Both rigid motions of the header give zero strain.
    struct HarmonicStrain
    {
      double rr, phiphi, zz, rz; // cos phi part
      double rphi, zphi;         // sin phi part

      HarmonicStrain(const std::array<double, 3> &value, const std::array<dealii::Tensor<1, 2>, 3> &gradient, double r)
        : rr(gradient[0][0])
        , phiphi((value[0] - value[1]) / r)
        , zz(gradient[2][1])
        , rz(gradient[0][1] + gradient[2][0])
        , rphi(-(gradient[1][0] + (value[0] - value[1]) / r))
        , zphi(-(gradient[1][1] + value[2] / r))
      {}
    };

    /// Isotropic Hooke's law on the two parts; the strain energy density averaged over phi is
    /// (cos part + sin part)/2, and its integral over phi gives the factor pi of the bilinear form.
    struct Hooke
    {
      double lambda, mu;

      /// eps : C : eps' for the cos part plus the sin part (the integrand of a(u, v) / pi).
      double energy_product(const HarmonicStrain &e, const HarmonicStrain &f) const
      {
        const double tr_e = e.rr + e.phiphi + e.zz, tr_f = f.rr + f.phiphi + f.zz;
        return lambda * tr_e * tr_f + 2 * mu * (e.rr * f.rr + e.phiphi * f.phiphi + e.zz * f.zz) +
               mu * (e.rz * f.rz + e.rphi * f.rphi + e.zphi * f.zphi);
      }

      struct Stress
      {
        double rr, phiphi, zz, rz, rphi, zphi;
        /// von Mises stress squared = A cos^2 phi + B sin^2 phi: the normal stresses and tau_rz
        /// scale with cos phi, tau_rphi and tau_zphi with sin phi.
        double von_mises_cos_part() const
        {
          return 0.5 * ((rr - phiphi) * (rr - phiphi) + (phiphi - zz) * (phiphi - zz) + (zz - rr) * (zz - rr)) +
                 3 * rz * rz;
        }
        double von_mises_sin_part() const { return 3 * (rphi * rphi + zphi * zphi); }
      };

      Stress stress(const HarmonicStrain &e) const
      {
        const double tr = e.rr + e.phiphi + e.zz;
        return {lambda * tr + 2 * mu * e.rr, lambda * tr + 2 * mu * e.phiphi, lambda * tr + 2 * mu * e.zz,
                mu * e.rz, mu * e.rphi, mu * e.zphi};
      }
    };

  } // namespace spring_tube_field

  struct SpringTubeField::Implementation
  {
    laws::SpringTubeGeometry geometry;
    spring_tube_field::Hooke hooke;
    SpringTubeFieldOptions options;

    dealii::Triangulation<2> triangulation;
    dealii::FESystem<2> fe;
    dealii::DoFHandler<2> dof_handler;
    dealii::SparsityPattern sparsity_pattern;
    dealii::SparseMatrix<double> stiffness_matrix;  // a(u, v), unconstrained
    dealii::SparseMatrix<double> constrained_matrix; // clamped and rigid DOFs eliminated (identity rows)
    dealii::SparseDirectUMFPACK direct_solver;
    std::map<dealii::types::global_dof_index, double> base_values, rotation_values, translation_values;
    dealii::Vector<double> unit_rotation, unit_translation; // solutions for theta = 1 and for delta = 1
    Matrix2 top_stiffness{};
    double z_top = 0;
    std::vector<double> section_changes; // heights of the base, the junctions and the top

    Implementation(const laws::SpringTubeGeometry &g, double E, double nu, const SpringTubeFieldOptions &o)
      : geometry(g)
      , hooke{E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))}
      , options(o)
      , fe(dealii::FE_Q<2>(o.element_degree), 3)
      , dof_handler(triangulation)
    {}

    void make_grid();
    void setup_system();
    void assemble_system();
    dealii::Vector<double> solve(const std::map<dealii::types::global_dof_index, double> &top_values);

    /// Calls `f(cell, q, point, strain)' at each point of `quadrature' in every cell, for the displacement u.
    template <typename F>
    void for_each_point(const dealii::Vector<double> &u, const dealii::Quadrature<2> &quadrature, F &&f) const
    {
      using namespace dealii;
      FEValues<2> fe_values(fe, quadrature, update_values | update_gradients | update_quadrature_points);
      std::vector<Vector<double>> values(quadrature.size(), Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> gradients(quadrature.size(), std::vector<Tensor<1, 2>>(3));
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(u, values);
          fe_values.get_function_gradients(u, gradients);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> &x = fe_values.quadrature_point(q);
              f(cell, q, x, spring_tube_field::HarmonicStrain({values[q][0], values[q][1], values[q][2]},
                                           {gradients[q][0], gradients[q][1], gradients[q][2]}, x[0]));
            }
        }
    }

    /// Strain of u at a point of the meridian section (on a boundary, from the cell that holds it).
    spring_tube_field::HarmonicStrain strain_at(const dealii::Vector<double> &u, const dealii::Point<2> &x) const
    {
      using namespace dealii;
      const auto [cell, unit_point] = GridTools::find_active_cell_around_point(MappingQ1<2>(), dof_handler, x);
      AssertThrow(cell.state() == IteratorState::valid, ExcMessage("spring tube field: point outside the tube"));
      const Quadrature<2> point(GeometryInfo<2>::project_to_unit_cell(unit_point));
      FEValues<2> fe_values(fe, point, update_values | update_gradients);
      fe_values.reinit(cell);
      std::vector<Vector<double>> value(1, Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> gradient(1, std::vector<Tensor<1, 2>>(3));
      fe_values.get_function_values(u, value);
      fe_values.get_function_gradients(u, gradient);
      return spring_tube_field::HarmonicStrain({value[0][0], value[0][1], value[0][2]}, {gradient[0][0], gradient[0][1], gradient[0][2]},
                            x[0]);
    }

    dealii::Vector<double> displacement(const TopLoad &load) const
    {
      const auto C = compliance();
      const double theta = C[0][0] * load.moment + C[0][1] * load.shear;
      const double delta = C[1][0] * load.moment + C[1][1] * load.shear;
      dealii::Vector<double> u(unit_rotation);
      u *= theta;
      u.add(delta, unit_translation);
      return u;
    }

    Matrix2 compliance() const
    {
      const auto &S = top_stiffness;
      const double det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
      return {{{S[1][1] / det, -S[0][1] / det}, {-S[1][0] / det, S[0][0] / det}}};
    }
  };
} // namespace servodrift::structure
