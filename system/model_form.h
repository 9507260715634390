#pragma once
// The model-form uncertainty of the pilot stage (issue 28): the flow stage computes the tables of
// `Pilot stage/Field solution/Model-form alternatives' beside the default's (tables/<table>.<model>.csv); here the
// same stage coefficients are read off each of them through the same valve model, and their spread
// about the default's at every drift temperature is what the choice of flow model leaves open:
// C_dn and the flapper force at the null, and the flow-force stiffness K_f (E24).
#include "common/valve_description.h"
#include "system/plots.h"
#include "system/stage_coefficients.h"
#include "system/stage_tables.h"

#include <ostream>
#include <string>
#include <vector>

namespace servodrift::system
{
  struct ModelFormCoefficients
  {
    std::string model;                           ///< the flow model of the tables ("default" for tables/*.csv)
    std::vector<StageCoefficients> coefficients; ///< at the drift temperatures
    std::size_t flagged_rows = 0;                ///< rows of its pilot tables not computed (flag 2)
  };

  /// The default's coefficients and each alternative's whose tables are in `tables_directory'; an
  /// alternative listed without its tables adds a warning (its flow stage has not run).
  std::vector<ModelFormCoefficients> model_form_coefficients(const ValveDescription &valve, const StageTables &tables,
                                                             const std::vector<StageCoefficients> &default_coefficients,
                                                             const std::string &tables_directory,
                                                             std::vector<std::string> &warnings);

  /// (The writers run on rank 0, inside the system stage's output.)
  /// system/model_form_spread.csv: every model's C_dn, flapper force and K_f at each drift
  /// temperature, and their deviation from the default's.
  void write_model_form_table(const ValveDescription &valve, const std::vector<ModelFormCoefficients> &models,
                              const std::string &directory);
  /// The band (the models' range) about the default of C_dn, the flapper force and K_f vs temperature.
  void write_model_form_plots(const ValveDescription &valve, const std::vector<ModelFormCoefficients> &models,
                              const std::string &directory, PlotFiles &files);
  /// The report's section.
  void model_form_section(std::ostream &out, const std::vector<ModelFormCoefficients> &models);
} // namespace servodrift::system
