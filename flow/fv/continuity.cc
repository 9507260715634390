#include "flow/fv/continuity.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  std::vector<double> cell_mass_imbalance(const FvMesh &mesh, const std::vector<double> &flux,
                                          const CavitationModel &cavitation, const TimeLevel *time, double density)
  {
    std::vector<double> imbalance(mesh.n_cells(), 0.0);
    mesh.for_each_face(
      [&](std::size_t f, unsigned int P, unsigned int N) {
        const double mF = cavitation.face_mixture_ratio(f, flux[f]) * flux[f];
        imbalance[P] += mF;
        imbalance[N] -= mF;
      },
      [&](std::size_t f, unsigned int P) { imbalance[P] += cavitation.face_mixture_ratio(f, flux[f]) * flux[f]; });
    if (time && time->dt > 0 && cavitation.enabled())
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        if (!cavitation.cell_cavitates(c))
          imbalance[c] += density * mesh.cell_volume[c] / time->dt * (time->new_weight() - time->old_mass(c));
    return imbalance;
  }

  double liquid_imbalance_sum(const std::vector<double> &imbalance, const CavitationModel &cavitation)
  {
    double sum = 0;
    for (std::size_t c = 0; c < imbalance.size(); ++c)
      if (!cavitation.cell_cavitates(c))
        sum += std::abs(imbalance[c]);
    return sum;
  }

  double continuity_reference(const FvMesh &mesh, const std::vector<double> &F, double velocity_inlet_inflow)
  {
    double inflow = 0, outflow = 0, circulation = 0;
    mesh.for_each_face([&](std::size_t f, unsigned int, unsigned int) { circulation += std::abs(F[f]); },
                       [&](std::size_t f, unsigned int) {
                         inflow += std::max(0.0, -F[f]), outflow += std::max(0.0, F[f]);
                       });
    return velocity_inlet_inflow > 0          ? velocity_inlet_inflow :
           std::max(inflow, outflow) > 0 ? std::max(inflow, outflow) :
                                           circulation / std::sqrt(double(mesh.n_cells()));
  }
} // namespace servodrift::flow
