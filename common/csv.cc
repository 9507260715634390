#include "common/csv.h"

#include "common/output_files.h"

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
          {
            if (is_non_finite_token(r[k]))
              throw std::runtime_error("a result is not a finite number: column " + columns[k] + ", row " +
                                       std::to_string(&r - rows.data() + 1) + " (" + r[k] +
                                       "); nothing was written. This is a defect of servodrift: please report "
                                       "it with the parameter file");
            s += (k ? "," : "") + r[k];
          }
        s += "\n";
      }
    return s;
  }
} // namespace servodrift
