#include "common/parameters/model_level.h"

#include <stdexcept>

namespace servodrift
{
  std::string to_string(ModelLevel level) { return level == ModelLevel::field ? "field" : "reduced-order"; }

  ModelLevel parse_model_level(const std::string &text)
  {
    if (text == "field")
      return ModelLevel::field;
    if (text == "reduced-order")
      return ModelLevel::reduced_order;
    throw std::logic_error("`Model level' = " + text + " passed its pattern"); // the pattern refuses it first
  }
} // namespace servodrift
