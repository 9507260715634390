#include "common/parameters/parameter_helpers.h"

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
} // namespace servodrift::parameters
