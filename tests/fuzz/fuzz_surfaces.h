#pragma once
// The newer surfaces (issue 62): `servodrift tolerances', `dynamics' and `calibrate', each run on a copy
// of the pre-filled output directory (it holds the coefficient tables they read), with hostile entries
// of their subsections and, for `calibrate', hostile measured-data files and --free entries.
#include "fuzz_mutations.h"
#include "fuzz_values.h"

#include <string>
#include <utility>
#include <vector>

namespace fuzz
{
  /// One entry set to a value: "Subsection/Key" (or "Tolerances/Quantity/Key") and the value.
  using Setting = std::pair<std::string, std::string>;

  /// A value at, just inside or beyond an end of `r' (a list of such values for a list entry). With
  /// `costly_end' the upper end is never drawn as such (only beyond it): values such as Samples =
  /// 10^7 are valid and merely slow, and a timeout on them would be the driver's fault.
  Replacement range_value(Rng &rng, const Range &r, bool costly_end);

  /// Entry `path' at or beyond its declared range (a bad value if it has none); the label says which.
  Setting range_setting(Rng &rng, const Context &c, const std::string &path, std::string &label);

  /// The entries under `prefix' ("Dynamics/") that have a declared numeric range.
  std::vector<std::string> ranged_entries(const Context &c, const std::string &prefix);

  /// A bad value (bytes, non-finite, lists, another entry's value) of one entry under any of
  /// `prefixes' ("Dynamics/"), appended to `hostile' with its label; false if there is no such entry.
  bool bad_entry_under(Rng &rng, const Context &c, const std::vector<std::string> &prefixes,
                       std::vector<Setting> &hostile, std::vector<std::string> &labels);

  /// An entry the system model reads beside the tables (Operating conditions, Sweeps, Fluid, Spool, ...)
  /// at or beyond its range: it may disagree with the tables the output directory holds.
  Setting valve_range_setting(Rng &rng, const Context &c, std::string &label);

  /// One table of the pre-filled output directory broken (a number non-finite or overflowing, a line
  /// deleted or repeated, provenance edited, truncated, bytes) into m.out_files; returns what was done.
  std::string broken_table(Rng &rng, const Context &c, Mutation &m);

  /// Arguments of `servodrift COMMAND [positionals] [valve] -o out' with the fixed --sets, the `base'
  /// settings (speed, a valid configuration) and the `hostile' ones, which win over a base setting of
  /// the same entry. The settings go in as --set options, or in a valve file (the default one or its
  /// JSON form, edited) placed before or after the options; m.description gets how.
  void surface_args(Rng &rng, const Context &c, Mutation &m, const std::string &command,
                    const std::vector<std::string> &positionals, const std::vector<Setting> &base,
                    const std::vector<Setting> &hostile);

  Mutation tolerances_mutation(Rng &rng, const Context &c);
  Mutation dynamics_mutation(Rng &rng, const Context &c);
  Mutation calibrate_mutation(Rng &rng, const Context &c);
} // namespace fuzz
