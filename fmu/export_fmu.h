#pragma once
// `servodrift export-fmu': the valve of a run's tables as an FMI 2.0 archive
// <output>/servodrift_valve.fmu (modelDescription.xml, binaries/linux64/servodrift_valve.so,
// resources/ with the tables, parameters.prm and provenance.txt, documentation/index.html).
#include "common/valve_description.h"

#include <string>

namespace servodrift::fmu
{
  struct ExportedFmu
  {
    std::string path;               ///< the archive
    double lowest_temperature = 0;  ///< the tables' common range [degC]
    double highest_temperature = 0; ///< [degC]
    std::size_t variables = 0;
  };

  /// The FMU's binary: servodrift_valve.so beside the running program. Throws InputError if absent.
  std::string fmu_library();

  /// Writes the archive from the tables in <output>/tables (read and checked as the system model
  /// reads them) and the valve description. Throws InputError (no tables, no binary).
  ExportedFmu export_fmu(const ValveDescription &valve);
} // namespace servodrift::fmu
