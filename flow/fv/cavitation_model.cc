#include "flow/fv/cavitation_model.h"

#include <algorithm>
#include <limits>

namespace servodrift::flow
{
  namespace
  {
    /// Gauss-Seidel sweeps of the liquid fractions per outer iteration: upwind chains of cavitating
    /// cells pass their mixture on by one cell per sweep
    constexpr int liquid_fraction_sweeps = 4;
  } // namespace

  CavitationModel::CavitationModel(const FvMesh &mesh_, double vapour_density_ratio)
    : gamma(mesh_.n_cells(), 1.0)
    , cavitating(mesh_.n_cells(), 0)
    , mixture_flux(mesh_.n_faces(), 0.0)
    , entered(mesh_.n_cells(), 0)
    , mesh(mesh_)
    , vapour_ratio(vapour_density_ratio)
    , floor(std::numeric_limits<double>::lowest())
  {}

  void CavitationModel::enable(double vapour_pressure)
  {
    on = true;
    floor = vapour_pressure;
  }

  void CavitationModel::update_mixture_flux(const std::vector<double> &flux)
  {
    mixture_flux.resize(mesh.n_faces());
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      mixture_flux[f] = face_mixture_ratio(f, flux[f]) * flux[f];
  }

  /// Upwind: gamma~_P sum(out) F = sum(in) gamma~_upwind |F| with gamma~ the mixture ratio, in
  /// Gauss-Seidel sweeps; then gamma = (gamma~ - r)/(1 - r), at least 0. With a time step, the
  /// storage S = rho V/dt joins both sides (flow_state.h's weights: implicit Euler or BDF2):
  /// gamma~_P (sum(out) F + w_new S) = sum(in) ... + S sum(w_old gamma~_old).
  void CavitationModel::update_liquid_fraction(const std::vector<double> &flux, const TimeLevel *time, double density)
  {
    const bool transient = time && time->dt > 0;
    for (int sweep = 0; sweep < liquid_fraction_sweeps; ++sweep)
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        {
          if (!cavitating[c])
            continue;
          double in = 0, out = 0;
          if (transient)
            {
              const double storage = density * mesh.cell_volume[c] / time->dt;
              in += storage * time->old_mass(c), out += storage * time->new_weight();
            }
          for (unsigned int f : mesh.cell_faces[c])
            {
              const double F = mesh.owner[f] == c ? flux[f] : -flux[f]; // out of c
              if (F > 0)
                out += F;
              else if (F < 0)
                in += -F * (mesh.neighbour[f] < 0 ? 1.0 : mixture_ratio(mesh.owner[f] == c ? mesh.neighbour[f] : mesh.owner[f]));
            }
          if (out <= vanishing * (in + 1))
            continue; // stagnant: keep
          const double mixture = in / out;
          if (mixture >= 1 && !(transient && entered[c]))
            cavitating[c] = 0, gamma[c] = 1;
          else
            gamma[c] = std::clamp((mixture - vapour_ratio) / (1 - vapour_ratio), 0.0, 1.0);
        }
    std::fill(entered.begin(), entered.end(), 0);
  }

  std::size_t CavitationModel::n_cavitating() const
  {
    return static_cast<std::size_t>(std::count(cavitating.begin(), cavitating.end(), 1));
  }
} // namespace servodrift::flow
