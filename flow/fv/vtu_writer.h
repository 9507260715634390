#pragma once
// VTU output of finite-volume fields through the VTK library (ParaView opens it).
#include "flow/fv/fv_mesh.h"

#include <string>
#include <vector>

namespace servodrift::flow
{
  /// Cells (triangles, quadrilaterals) with p, velocity (3 components), cell_id, boundary_id = -1;
  /// then one line cell per boundary face with its boundary values, cell_id = -1 and boundary_id =
  /// its patch (the patch names are in the field data "boundary_names"). Extra cell fields go as
  /// named arrays (`extra': name -> values per cell). Written to a temporary file and renamed.
  void write_fv_vtu(const std::string &filename, const FvMesh &mesh, const std::vector<double> &p,
                    const std::vector<double> &u, const std::vector<double> &v, const std::vector<double> &p_b,
                    const std::vector<double> &u_b, const std::vector<double> &v_b,
                    const std::vector<std::pair<std::string, std::vector<double>>> &extra = {});
} // namespace servodrift::flow
