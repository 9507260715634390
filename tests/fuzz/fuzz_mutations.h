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
    n_categories
  };
  inline const std::array<const char *, n_categories> category_names{"value", "structure", "json", "command-line"};

  /// What a run gives servodrift: the files to write in the run directory, the arguments, and what
  /// the checks need to know about it.
  struct Mutation
  {
    Category category = value_category;
    std::string description;
    std::map<std::string, std::string> files; ///< name in the run directory -> content
    std::string fifo, directory;              ///< a FIFO or directory to create in the run directory
    std::vector<std::string> args;            ///< after `servodrift'
    bool uses_secret = false;                 ///< an included file holds the secret marker
    bool expect_success = false;              ///< valid input: a refusal is itself a failure
  };

  /// Everything the mutations draw from.
  struct Context
  {
    std::string servodrift;
    Prm prm;
    std::string prm_text, json_text;
    std::vector<std::string> fixed_sets; ///< the --set options of every run (reduced order, no plots)
    std::vector<std::string> values;     ///< every entry's default value
    bool unmutated_run_failed = false;   ///< the pre-fill run broke a promise itself
  };

  inline const std::string secret_tag = "FUZZSECRET";

  /// A random mutation of any kind (value, structure, JSON form, command line), weighted.
  Mutation mutation(Rng &rng, const Context &c);
} // namespace fuzz
