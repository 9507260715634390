#pragma once
// CSV text with a '#' comment header: the format of the coefficient tables and of every CSV output.
#include <string>
#include <vector>

namespace servodrift
{
  struct CsvDocument
  {
    std::vector<std::string> comments;          ///< header lines, written as "# <line>"
    std::vector<std::string> columns;           ///< "name[unit]"
    std::vector<std::vector<std::string>> rows; ///< cells; an empty cell means "not defined"

    /// The comments, a "# columns ..." line, the column header row and the rows.
    std::string text() const;
    /// The document that text() wrote: the '#' lines its comments (without the "# columns" line),
    /// the first other line its columns, the rest its rows, cells split at commas (its cells hold
    /// none).
    static CsvDocument parse(const std::string &text);
    /// The index of the column `name' ("name[unit]"); throws std::out_of_range if there is none.
    std::size_t column(const std::string &name) const;
  };

  /// One field of a CSV record in double quotes, its quotes doubled (RFC 4180): for free text, as the
  /// records of the tests' checks and the benchmarks' figures hold it.
  inline std::string quoted_csv_field(const std::string &text)
  {
    std::string quoted = "\"";
    for (char c : text)
      quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
  }
} // namespace servodrift
