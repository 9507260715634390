#include "common/vtu_output.h"

#include "common/error.h"
#include "common/output_files.h"

#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <unistd.h>

#include <cstdio>

namespace servodrift
{
  void write_vtu_atomically(const std::string &filename, vtkUnstructuredGrid *grid)
  {
    const std::string temporary = filename + ".tmp." + std::to_string(::getpid()) + ".vtu";
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToBinary();
    if (writer->Write() != 1)
      {
        std::remove(temporary.c_str());
        throw InputError(filename + ": VTK could not write the file");
      }
    install_file(temporary, filename);
  }

  void write_pvd_atomically(const std::string &filename, const std::vector<std::pair<double, std::string>> &datasets)
  {
    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (const auto &[timestep, file] : datasets)
      pvd += "    <DataSet timestep=\"" + format_cell(timestep) + "\" part=\"0\" file=\"" + file + "\"/>\n";
    pvd += "  </Collection>\n</VTKFile>\n";
    write_file_atomically(filename, pvd);
  }
} // namespace servodrift
