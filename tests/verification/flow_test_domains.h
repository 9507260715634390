#pragma once
// The domains the flow-solver verification tests share (flow_core_test.cc, flow_turbulence_test.cc,
// flow_field_transfer_test.cc): the rectangle of tests/verification/meshes/rectangle.geo, the
// solver settings of the built-in valve to a tolerance, and the pipe's boundary conditions.
#include "common/gmsh_mesh.h"
#include "common/output_files.h"
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"
#include "tests/support/test_support.h"

#include <map>
#include <string>

namespace servodrift::flow::domains
{
  /// The rectangle [x0, x1] x [y0, y1] of tests/verification/meshes/rectangle.geo: nx x ny
  /// quadrilaterals, graded towards y0 and y1 by `bump' (1: uniform), or triangles of about that size.
  inline FvMesh rectangle(Geometry geometry, double x0, double x1, double y0, double y1, int nx, int ny,
                          bool triangles = false, double bump = 1)
  {
    static const GmshTemplate geo{"rectangle.geo", read_file(std::string(SERVODRIFT_SOURCE_DIR) + "/tests/verification/meshes/rectangle.geo"),
                                  1.0, ""};
    const PlanarMesh m = mesh_template_all_groups(geo, {{"x0", x0},
                                                        {"x1", x1},
                                                        {"y0", y0},
                                                        {"y1", y1},
                                                        {"nx", double(nx)},
                                                        {"ny", double(ny)},
                                                        {"tri", triangles ? 1.0 : 0.0},
                                                        {"bump", bump}});
    return FvMesh(m, geometry, "rectangle.geo");
  }

  /// A flow model's name in a parametrised test's name (letters only, as gtest asks).
  inline std::string test_name(FlowSolverParameters::Turbulence t)
  {
    switch (t)
      {
        case FlowSolverParameters::Turbulence::laminar: return "Laminar";
        case FlowSolverParameters::Turbulence::k_epsilon: return "TwoLayer";
        case FlowSolverParameters::Turbulence::k_epsilon_launder_sharma: return "LaunderSharma";
        case FlowSolverParameters::Turbulence::k_omega_sst: return "SST";
      }
    return "Unknown";
  }

  /// The built-in valve's flow-solver settings, to `tolerance'.
  inline FlowSolverParameters settings(double tolerance = 1e-8)
  {
    FlowSolverParameters s = test::valve().flow_solver;
    s.tolerance = tolerance;
    return s;
  }

  /// A pipe of the rectangle template: `inlet' on the left, a static-pressure outlet (0) on the
  /// right, the wall on top, the axis at the bottom.
  inline std::map<std::string, BoundaryCondition> pipe_boundaries(const BoundaryCondition &inlet)
  {
    return {{"left", inlet},
            {"right", BoundaryCondition::pressure_outlet(0)},
            {"top", BoundaryCondition::wall()},
            {"bottom", BoundaryCondition::axis()}};
  }
} // namespace servodrift::flow::domains
