#pragma once
#include <string>

namespace servodrift
{
  /// A stage's level of modelling (D13): the closed forms of model.md section 1, or the field solver
  /// of section 4 (finite elements for the torque motor and the spring tube, finite volumes for the
  /// pilot stage). Each stage's `Model level' entry, parsed once.
  enum class ModelLevel
  {
    reduced_order,
    field
  };

  /// "reduced-order" or "field", as a parameter file spells it and the outputs name it
  std::string to_string(ModelLevel level);
  /// The level a `Model level' entry names (its pattern admits only "reduced-order" and "field")
  ModelLevel parse_model_level(const std::string &text);
} // namespace servodrift
