#include "common/csv.h"

#include <stdexcept>

namespace servodrift
{
  std::string CsvDocument::text() const
  {
    std::string s;
    for (const auto &c : comments)
      s += "# " + c + "\n";
    s += "# columns";
    for (const auto &c : columns)
      s += " " + c;
    s += "\n";
    for (std::size_t k = 0; k < columns.size(); ++k)
      s += (k ? "," : "") + columns[k];
    s += "\n";
    for (const auto &r : rows)
      {
        if (r.size() != columns.size())
          throw std::logic_error("CsvDocument: a row has " + std::to_string(r.size()) + " cells for " +
                                 std::to_string(columns.size()) + " columns");
        for (std::size_t k = 0; k < r.size(); ++k)
          s += (k ? "," : "") + r[k];
        s += "\n";
      }
    return s;
  }
} // namespace servodrift
