#pragma once
// Writing a VTK unstructured grid as a VTU file (ParaView) without ever leaving a half-written one.
#include <string>
#include <utility>
#include <vector>

class vtkUnstructuredGrid;

namespace servodrift
{
  /// Writes `grid' (binary VTU) to a temporary file beside `filename', then renames it. Throws
  /// InputError naming the file if VTK cannot write it.
  void write_vtu_atomically(const std::string &filename, vtkUnstructuredGrid *grid);

  /// Writes a ParaView collection (.pvd) of `datasets' (timestep, file name relative to the
  /// collection), atomically.
  void write_pvd_atomically(const std::string &filename, const std::vector<std::pair<double, std::string>> &datasets);
} // namespace servodrift
