#include "common/parameters/parameter_helpers.h"

#include <deal.II/base/utilities.h>

namespace servodrift::parameters
{
  Patterns::List double_list(double min, double max, unsigned int min_elements)
  {
    return Patterns::List(Patterns::Double(min, max), min_elements);
  }

  Patterns::List integer_list(int min, int max, unsigned int min_elements, unsigned int max_elements)
  {
    return Patterns::List(Patterns::Integer(min, max), min_elements, max_elements);
  }

  std::vector<double> get_double_list(const ParameterHandler &prm, const std::string &key)
  {
    return dealii::Utilities::string_to_double(dealii::Utilities::split_string_list(prm.get(key)));
  }

  std::vector<int> get_integer_list(const ParameterHandler &prm, const std::string &key)
  {
    return dealii::Utilities::string_to_int(dealii::Utilities::split_string_list(prm.get(key)));
  }
} // namespace servodrift::parameters
