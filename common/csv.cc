#include "common/csv.h"

#include "common/output_files.h"

#include <algorithm>
#include <sstream>
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

  CsvDocument CsvDocument::parse(const std::string &text)
  {
    CsvDocument doc;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty())
          continue;
        if (line[0] == '#')
          {
            if (line.rfind("# columns", 0) != 0)
              doc.comments.push_back(line.substr(line.size() > 1 && line[1] == ' ' ? 2 : 1));
            continue;
          }
        std::vector<std::string> cells;
        std::istringstream fields(line);
        for (std::string cell; std::getline(fields, cell, ',');)
          cells.push_back(cell);
        if (doc.columns.empty())
          doc.columns = cells;
        else
          doc.rows.push_back(cells);
      }
    return doc;
  }

  std::size_t CsvDocument::column(const std::string &name) const
  {
    const auto k = std::find(columns.begin(), columns.end(), name);
    if (k == columns.end())
      throw std::out_of_range("no column " + name);
    return static_cast<std::size_t>(k - columns.begin());
  }
} // namespace servodrift
