// What a solution of the A_z equation gives (model.md 4.1): the force or torque on the body by the
// weighted Maxwell stress tensor and by virtual work, the coenergy, flux densities, the VTU file.
#include "magnetics/magnetostatic_problem_implementation.h"

#include "common/output_files.h"
#include "common/units.h"

#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace servodrift::magnetics
{
  using units::mu0;
  using detail::flux_density;

  double MagnetostaticProblem::stress_tensor_force() const
  {
    // F = -w_d int_air T_M : grad V dA, T_M = nu0 (B (x) B - |B|^2/2 I), over the morphing air where V
    // goes from the body's velocity to zero (4.1 item 2)
    const auto &d = *impl;
    const double nu0 = 1 / mu0;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients | update_JxW_values);
    FEValues<2> morph_values(d.fe_morph, d.quadrature, update_gradients);
    const unsigned int n_q = d.quadrature.size();
    std::vector<Tensor<1, 2>> grad_A(n_q), grad_Vx(n_q), grad_Vy(n_q);
    double integral = 0;
    auto morph_cell = d.morph_dof_handler.begin_active();
    for (auto cell = d.dof_handler.begin_active(); cell != d.dof_handler.end(); ++cell, ++morph_cell)
      {
        if (!d.material(cell).morphing)
          continue;
        fe_values.reinit(cell);
        morph_values.reinit(morph_cell);
        fe_values.get_function_gradients(d.solution, grad_A);
        morph_values.get_function_gradients(d.velocity[0], grad_Vx);
        morph_values.get_function_gradients(d.velocity[1], grad_Vy);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Tensor<1, 2> B = flux_density(grad_A[q]);
            const double b2 = B * B;
            const double div_V = grad_Vx[q][0] + grad_Vy[q][1];
            const double BgradVB = B[0] * (B * grad_Vx[q]) + B[1] * (B * grad_Vy[q]);
            integral += nu0 * (BgradVB - 0.5 * b2 * div_V) * fe_values.JxW(q);
          }
      }
    return -d.depth * integral;
  }

  double MagnetostaticProblem::coenergy() const
  {
    // W' = w_d int w'(H) dA equals w_d (int J A dA - int w(B) dA) at the solution (the weak form with
    // the solution as test function gives int H . B = int J A, and w' = B . H - w), and the latter is
    // minus the energy functional whose stationary point the solution is: its error is quadratic in
    // the solution's, so virtual work's solves may stop well short of the tolerance.
    const auto &d = *impl;
    const unsigned int dofs_per_cell = d.fe.n_dofs_per_cell(), n_q = d.quadrature.size();
    double W = 0;
    for (std::size_t c = 0; c < d.cell_material.size(); ++c)
      {
        const Material &m = *d.cell_material[c];
        const double J = m.current_density * d.current;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const std::size_t cq = c * n_q + q;
            Tensor<1, 2> grad_A;
            double A = 0;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const double A_i = d.solution[d.cell_dofs[c * dofs_per_cell + i]];
                grad_A += A_i * d.cell_geometry.shape_gradients[cq * dofs_per_cell + i];
                A += A_i * d.shape_values(q, i);
              }
            const Tensor<1, 2> B = flux_density(grad_A);
            const double b2 = B * B;
            double w = 0; // energy density w = int_0^B H . dB'
            switch (m.kind)
              {
                case Material::Kind::air:
                case Material::Kind::linear:
                  w = 0.5 * b2 / (mu0 * m.relative_permeability); // B^2/(2 mu)
                  break;
                case Material::Kind::magnet:
                  {
                    // H = (B - B_r)/mu_m: w = mu_m |H|^2/2
                    const double mu_m = mu0 * m.relative_permeability;
                    const double Hx = (B[0] - m.remanence[0]) / mu_m, Hy = (B[1] - m.remanence[1]) / mu_m;
                    w = 0.5 * mu_m * (Hx * Hx + Hy * Hy);
                    break;
                  }
                case Material::Kind::nonlinear:
                  {
                    const double b = std::sqrt(b2), H = m.curve->field_strength(b);
                    w = b * H - m.curve->coenergy_density(H); // Legendre: w = B H - w'(H)
                    break;
                  }
              }
            W += (J * A - w) * d.cell_geometry.JxW[cq];
          }
      }
    return d.depth * W;
  }

  double MagnetostaticProblem::virtual_work_force(double step)
  {
    auto &d = *impl;
    const double s0 = d.s, current = d.current;
    // the state at s0, restored afterwards without recomputing it (its cell geometry kept aside by a
    // swap, whose buffers the solves at s0 +- step then fill)
    const Vector<double> A0 = d.solution;
    std::swap(d.cell_geometry, d.kept_cell_geometry);
    const auto velocity0 = d.velocity;
    const std::vector<Point<2>> vertices0 = d.triangulation.get_vertices();
    // Each solve starts from a prediction: +step to first order from the tangent that the last
    // position left at this current (if any), carried to s0 by its second derivative; -step by
    // reflecting the +step solution through A0. The three solutions then give dA/ds and d2A/ds2 at
    // s0 for the next position's solve.
    const bool tangent_known = d.tangent.known && d.tangent.current == current;
    d.move_to(s0 + step);
    d.solution = A0;
    if (tangent_known) // dA/ds at s0 from the last position's dA/ds and d2A/ds2
      d.solution.add(step, d.tangent.dA_ds, step * (s0 - d.tangent.position), d.tangent.d2A_ds2);
    // The coenergy is stationary in A (coenergy()): a solve stopped at a residual r leaves it within
    // about 500 r^2 of itself (RV-1, CoenergyIsStationaryInThePotential), so the solves at +-step
    // stop at 1e3 x the tolerance: at 1e-7, some 2e-9 of the torque in the virtual work, below 1e-4
    // of its difference from the stress tensor's.
    const double tolerance = d.tolerance, loose = 1e3 * tolerance;
    d.solve(current, loose, 50);
    const double W_plus = coenergy();
    const Vector<double> A_plus = d.solution;
    d.move_to(s0 - step);
    d.solution.sadd(-1, 2, A0); // 2 A0 - A_plus
    d.solve(current, loose, 50);
    d.tolerance = tolerance;
    const double W_minus = coenergy();
    d.tangent.dA_ds = A_plus;
    d.tangent.dA_ds.add(-1, d.solution);
    d.tangent.dA_ds /= 2 * step;
    d.tangent.d2A_ds2 = A_plus;
    d.tangent.d2A_ds2.add(-2, A0, 1, d.solution);
    d.tangent.d2A_ds2 /= step * step;
    d.tangent.A = A0;
    d.tangent.position = s0, d.tangent.current = current, d.tangent.known = true;
    for (const auto &cell : d.triangulation.active_cell_iterators())
      for (unsigned int v = 0; v < 4; ++v)
        cell->vertex(v) = vertices0[cell->vertex_index(v)];
    d.s = s0;
    std::swap(d.cell_geometry, d.kept_cell_geometry);
    d.velocity = velocity0;
    d.solution = A0;
    return (W_plus - W_minus) / (2 * step);
  }

  double MagnetostaticProblem::mean_flux_density(int material, unsigned int component) const
  {
    const auto &d = *impl;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients | update_JxW_values);
    std::vector<Tensor<1, 2>> grad_A(d.quadrature.size());
    double sum = 0, area = 0;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      if (static_cast<int>(cell->material_id()) == material)
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(d.solution, grad_A);
          for (unsigned int q = 0; q < grad_A.size(); ++q)
            {
              sum += flux_density(grad_A[q])[component] * fe_values.JxW(q);
              area += fe_values.JxW(q);
            }
        }
    return area > 0 ? sum / area : 0.0;
  }

  double MagnetostaticProblem::max_flux_density(int material) const
  {
    const auto &d = *impl;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients);
    std::vector<Tensor<1, 2>> grad_A(d.quadrature.size());
    double largest = 0;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      if (static_cast<int>(cell->material_id()) == material)
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(d.solution, grad_A);
          for (const auto &g : grad_A)
            largest = std::max(largest, g.norm());
        }
    return largest;
  }

  namespace
  {
    /// B, |B| and H from A_z, with the material of each cell.
    class FieldPostprocessor : public DataPostprocessor<2>
    {
    public:
      explicit FieldPostprocessor(const std::map<int, Material> &materials)
        : materials(materials)
      {}

      void evaluate_scalar_field(const DataPostprocessorInputs::Scalar<2> &inputs,
                                 std::vector<Vector<double>> &computed) const override
      {
        const auto cell = inputs.template get_cell<2>();
        const Material &m = materials.at(static_cast<int>(cell->material_id()));
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const Tensor<1, 2> B = flux_density(inputs.solution_gradients[q]);
            const double b = B.norm();
            double Hx, Hy;
            if (m.kind == Material::Kind::nonlinear)
              {
                const double nu = b > 0 ? m.curve->field_strength(b) / b : 0;
                Hx = nu * B[0], Hy = nu * B[1];
              }
            else
              {
                const double nu = 1 / (mu0 * m.relative_permeability);
                Hx = nu * (B[0] - m.remanence[0]), Hy = nu * (B[1] - m.remanence[1]);
              }
            computed[q] = Vector<double>{B[0], B[1], b, Hx, Hy};
          }
      }

      std::vector<std::string> get_names() const override { return {"B", "B", "B_magnitude", "H", "H"}; }

      std::vector<DataComponentInterpretation::DataComponentInterpretation> get_data_component_interpretation()
        const override
      {
        using I = DataComponentInterpretation::DataComponentInterpretation;
        return {I::component_is_part_of_vector, I::component_is_part_of_vector, I::component_is_scalar,
                I::component_is_part_of_vector, I::component_is_part_of_vector};
      }

      UpdateFlags get_needed_update_flags() const override { return update_gradients; }

    private:
      const std::map<int, Material> &materials;
    };
  } // namespace

  void MagnetostaticProblem::write_vtu(const std::string &filename) const
  {
    const auto &d = *impl;
    FieldPostprocessor postprocessor(d.materials);
    DataOut<2> data_out;
    data_out.attach_dof_handler(d.dof_handler);
    data_out.add_data_vector(d.solution, "A_z");
    data_out.add_data_vector(d.solution, postprocessor);
    Vector<float> material(d.triangulation.n_active_cells()), J(d.triangulation.n_active_cells());
    for (const auto &cell : d.triangulation.active_cell_iterators())
      {
        material[cell->active_cell_index()] = cell->material_id();
        J[cell->active_cell_index()] =
          d.materials.at(static_cast<int>(cell->material_id())).current_density * d.current;
      }
    data_out.add_data_vector(material, "material_id");
    data_out.add_data_vector(J, "current_density");
    data_out.build_patches(d.fe.degree);
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::ostringstream out;
    data_out.write_vtu(out);
    write_file_atomically(filename, out.str());
  }
} // namespace servodrift::magnetics
