#pragma once
// Error types shared by all modules. main() maps InputError and every other std::exception to exit
// code 1 and prints the message, which is one line naming what the user has to change.
#include <stdexcept>
#include <string>

namespace servodrift
{
  /// Bad input: a parameter file, an override, a table file or an output directory. The message is
  /// one line that names the file or entry, what is wrong and the allowed range.
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// A query outside the range of a coefficient table (names table, variable, value and range).
  class TableRangeError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Formats a double for a message: shortest form that keeps 6 significant digits.
  std::string format_number(double value);
} // namespace servodrift
