#pragma once
// Helpers for the .cc files that declare and parse parameters. This header includes deal.II's
// ParameterHandler; include it only from .cc files (keeps deal.II out of our headers).
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace servodrift::parameters
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  /// Comma-separated list of doubles, each within [min, max].
  Patterns::List double_list(double min, double max, unsigned int min_elements = 1);
  /// Comma-separated list of integers, each within [min, max].
  Patterns::List integer_list(int min, int max, unsigned int min_elements = 1,
                              unsigned int max_elements = Patterns::List::max_int_value);

  std::vector<double> get_double_list(const ParameterHandler &prm, const std::string &key);
  std::vector<int> get_integer_list(const ParameterHandler &prm, const std::string &key);
} // namespace servodrift::parameters
