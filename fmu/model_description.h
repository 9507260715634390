#pragma once
// modelDescription.xml of the valve FMU (FMI 2.0, both kinds), written from the variables' list.
#include "fmu/fmu_variables.h"

#include <string>

namespace servodrift::fmu
{
  struct ModelDescriptionInfo
  {
    std::string guid;            ///< "{...}": the FMU checks it against resources/provenance.txt
    std::string description;     ///< of the valve (its source and the tables' levels)
    std::string generation_tool; ///< "servodrift <version> (git <rev>)"
    std::string version;         ///< servodrift's
    std::string generated_at;    ///< ISO 8601, UTC
    double stop_time = 0.2;      ///< of the default experiment [s]
    double tolerance = 1e-6;     ///< relative, of the default experiment
  };

  std::string model_description(const Layout &layout, const ModelDescriptionInfo &info);
} // namespace servodrift::fmu
