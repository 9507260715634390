#pragma once
// One run's mutation: the Mutation and Context types, and the draw of a mutation of some kind.
#include "fuzz_description.h"
#include "fuzz_support.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace fuzz
{
  // ---- one run's mutation ------------------------------------------------------------------------------
  enum Category
  {
    value_category,
    structure_category,
    json_category,
    command_line_category,
    // the newer surfaces, each run on a copy of the pre-filled output directory (its tables)
    tolerances_category,
    dynamics_category,
    calibrate_category,
    n_categories
  };
  inline const std::array<const char *, n_categories> category_names{"value",      "structure", "json",     "command-line",
                                                                     "tolerances", "dynamics",  "calibrate"};

  /// What a run gives servodrift: the files to write in the run directory, the arguments, and what
  /// the checks need to know about it.
  struct Mutation
  {
    Category category = value_category;
    std::string description;
    std::map<std::string, std::string> files; ///< name in the run directory -> content
    std::string fifo, directory;              ///< a FIFO or directory to create in the run directory
    std::map<std::string, std::string> out_files; ///< written over the pre-filled output directory (a broken table)
    std::vector<std::string> args;            ///< after `servodrift'
    bool uses_secret = false;                 ///< an included file holds the secret marker
    bool expect_success = false;              ///< valid input: a refusal is itself a failure
    bool expect_refusal = false;              ///< input the documentation says is refused: exit 0 is a failure
    bool usage_allowed = false;               ///< a malformed command line: exit 2 is right
    bool tables = false;                      ///< needs the tables: the output directory is always pre-filled
  };

  /// Everything the mutations draw from.
  struct Context
  {
    std::string servodrift;
    Prm prm;
    std::string prm_text, json_text;
    std::vector<std::string> fixed_sets; ///< the --set options of every run (reduced order, no plots)
    std::vector<std::string> values;     ///< every entry's default value
    std::map<std::string, std::string> tables; ///< "tables/<name>" -> content, of the pre-filled directory
    std::map<std::string, Range> ranges; ///< every numeric entry's declared range
    /// valid measured drift data for `calibrate', made by the model with a known magnetic null
    std::vector<double> measured_temperatures, measured_null_shift, measured_brake_pressure; ///< degC, A, Pa
    double rated_current = 0.02;                                                          ///< A, of the brake pressure
    bool unmutated_run_failed = false;   ///< the pre-fill run broke a promise itself
  };

  inline const std::string secret_tag = "FUZZSECRET";

  /// A random mutation of one of the kinds `enabled' holds (value, structure, JSON form, command line,
  /// the tolerances, dynamics and calibrate surfaces), weighted.
  Mutation mutation(Rng &rng, const Context &c, const std::array<bool, n_categories> &enabled);
} // namespace fuzz
