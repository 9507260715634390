#include "flow/fv/limiter.h"

#include <algorithm>

namespace servodrift::flow
{
  std::vector<double> barth_jespersen_limiter(const FvMesh &mesh, const std::vector<double> &phi,
                                              const std::vector<double> &phi_b, const std::vector<Vector2> &grad)
  {
    std::vector<double> psi(mesh.n_cells(), 1.0);
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        double lo = phi[c], hi = phi[c];
        for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
          {
            const double o = mesh.value_across(k, phi, phi_b);
            lo = std::min(lo, o), hi = std::max(hi, o);
          }
        // psi = min over the faces of min(1, (phi_max - phi_c)/delta) where the reconstruction
        // delta = grad . (x_f - x_c) rises, (phi_min - phi_c)/delta where it falls
        for (std::size_t k = mesh.cell_face_offset[c]; k < mesh.cell_face_offset[c + 1]; ++k)
          {
            const double delta = grad[c].dot(mesh.cell_to_face[k]);
            if (delta > vanishing)
              psi[c] = std::min(psi[c], std::min(1.0, (hi - phi[c]) / delta));
            else if (delta < -vanishing)
              psi[c] = std::min(psi[c], std::min(1.0, (lo - phi[c]) / delta));
          }
      }
    return psi;
  }
} // namespace servodrift::flow
