#pragma once
// What the reading of a valve description (common/parameter_input.cc) says about the declared
// entries: their names for "did you mean", and a check that every number converts.
#include <optional>
#include <string>
#include <vector>

namespace dealii
{
  class ExceptionBase;
  class ParameterHandler;
} // namespace dealii

namespace servodrift
{
  /// The declared names under a subsection path: its subsections or its entries.
  std::vector<std::string> declared_names(const dealii::ParameterHandler &prm, const std::vector<std::string> &path,
                                          bool subsections);
  /// " (did you mean `X'?)" for the nearest of `names', if it is near enough to be a typo; else "".
  std::string suggestion(const std::string &given, const std::vector<std::string> &names);
  /// "A/B/C"
  std::string joined(const std::vector<std::string> &path);
  /// A deal.II exception's text, its whitespace runs as one space.
  std::string exception_text(const dealii::ExceptionBase &e);
  /// The pattern of ParameterHandler::set's "The string <v> does not match the given pattern <p>."
  /// (the value may hold anything: the last marker counts), or nothing for another error.
  std::optional<std::string> mismatched_pattern(const dealii::ExceptionBase &e);
  /// Every number of every Double entry converts to a finite, normal double (deal.II's pattern
  /// accepts a subnormal such as 1e-310; its conversion then fails with a raw exception). Throws
  /// InputError naming the entry.
  void check_numbers(const dealii::ParameterHandler &prm);
} // namespace servodrift
