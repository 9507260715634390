#include "common/table.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace servodrift
{
  namespace schemas
  {
    const TableSchema torque_motor{"torque_motor",
                                   1,
                                   {{"temperature", "degC"},
                                    {"angle", "rad"},
                                    {"current", "A"},
                                    {"torque", "N*m"},
                                    {"torque_error", "N*m"},
                                    {"flag", "1"}},
                                   3};
    const TableSchema spring_tube{"spring_tube", 1, {{"temperature", "degC"}, {"stiffness", "N*m/rad"}, {"flag", "1"}}, 1};
    const TableSchema fixed_orifice{"fixed_orifice",
                                    1,
                                    {{"temperature", "degC"},
                                     {"pressure_difference", "Pa"},
                                     {"flow_rate", "m^3/s"},
                                     {"discharge_coefficient", "1"},
                                     {"reynolds_number", "1"},
                                     {"flag", "1"}},
                                    2};
    const TableSchema nozzle_flapper{"nozzle_flapper",
                                     1,
                                     {{"temperature", "degC"},
                                      {"gap", "m"},
                                      {"pressure_difference", "Pa"},
                                      {"flow_rate", "m^3/s"},
                                      {"discharge_coefficient", "1"},
                                      {"reynolds_number", "1"},
                                      {"flapper_force", "N"},
                                      {"flag", "1"}},
                                     3};
    const TableSchema fixed_orifice_bore{"fixed_orifice_bore",
                                         1,
                                         {{"temperature", "degC"},
                                          {"pressure_difference", "Pa"},
                                          {"bore_step", "m"},
                                          {"flow_ratio", "1"},
                                          {"flag", "1"}},
                                         2};
    const TableSchema nozzle_flapper_bore{"nozzle_flapper_bore",
                                          1,
                                          {{"temperature", "degC"},
                                           {"gap", "m"},
                                           {"pressure_difference", "Pa"},
                                           {"bore_step", "m"},
                                           {"flow_ratio", "1"},
                                           {"force_ratio", "1"},
                                           {"flag", "1"}},
                                          3};

    const TableSchema &by_name(const std::string &name)
    {
      for (const TableSchema *s :
           {&torque_motor, &spring_tube, &fixed_orifice, &nozzle_flapper, &fixed_orifice_bore, &nozzle_flapper_bore})
        if (s->name == name)
          return *s;
      throw InputError("unknown table `" + name +
                       "' (known: torque_motor, spring_tube, fixed_orifice, nozzle_flapper, fixed_orifice_bore, "
                       "nozzle_flapper_bore)");
    }
  } // namespace schemas

  Table::Table(const TableSchema &schema)
    : table_schema(&schema)
  {}

  std::size_t Table::column_index(const std::string &name) const
  {
    for (std::size_t k = 0; k < table_schema->columns.size(); ++k)
      if (table_schema->columns[k].name == name)
        return k;
    throw std::logic_error("table " + table_schema->name + " has no column " + name);
  }

  std::vector<double> Table::column(const std::string &name) const
  {
    const std::size_t c = column_index(name);
    std::vector<double> out;
    out.reserve(rows.size());
    for (const auto &r : rows)
      out.push_back(r[c]);
    return out;
  }

  std::string Table::to_csv() const
  {
    CsvDocument doc;
    doc.comments = {"servodrift-table " + table_schema->name, "schema " + std::to_string(table_schema->version),
                    "producer " + producer, "parameters-sha256 " + parameters_sha256,
                    "rows " + std::to_string(rows.size())};
    for (const auto &note : notes)
      doc.comments.push_back("note " + note);
    for (const auto &c : table_schema->columns)
      doc.columns.push_back(c.header());
    for (const auto &r : rows)
      {
        if (r.size() != table_schema->columns.size())
          throw std::logic_error("table " + table_schema->name + ": row of wrong length");
        std::vector<std::string> cells;
        for (std::size_t k = 0; k < r.size(); ++k)
          {
            if (!std::isfinite(r[k]))
              throw std::logic_error("table " + table_schema->name + ": non-finite value in column " +
                                     table_schema->columns[k].name);
            cells.push_back(format_cell(r[k]));
          }
        doc.rows.push_back(std::move(cells));
      }
    return doc.text();
  }

  void Table::write(const std::string &path) const
  {
    write_file_atomically(path, to_csv());
  }

  namespace
  {
    std::vector<std::string> split(const std::string &line, char separator)
    {
      std::vector<std::string> out;
      std::string field;
      std::istringstream s(line);
      while (std::getline(s, field, separator))
        out.push_back(field);
      if (!line.empty() && line.back() == separator)
        out.emplace_back();
      return out;
    }

    std::string trim(const std::string &s)
    {
      const auto a = s.find_first_not_of(" \t\r");
      const auto b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? "" : s.substr(a, b - a + 1);
    }
  } // namespace

  Table Table::read(const std::string &path, const std::string &expected_name)
  {
    const std::string text = read_file(path);
    std::istringstream in(text);
    std::string line;
    int line_number = 0;
    auto where = [&](int l) { return path + ":" + std::to_string(l) + ": "; };
    auto header_line = [&](const std::string &key) {
      if (!std::getline(in, line))
        throw InputError(where(line_number + 1) + "file ends inside the header (truncated table?)");
      ++line_number;
      line = trim(line);
      const std::string prefix = "# " + key;
      if (line.rfind(prefix, 0) != 0)
        throw InputError(where(line_number) + "expected `" + prefix + " ...' in the table header, found `" +
                         line.substr(0, 60) + "'");
      return trim(line.substr(prefix.size()));
    };

    const std::string name = header_line("servodrift-table");
    if (name != expected_name)
      throw InputError(where(1) + "table `" + name + "' where a `" + expected_name + "' table was expected");
    const TableSchema &schema = schemas::by_name(expected_name);
    Table table(schema);
    const std::string schema_text = header_line("schema");
    if (schema_text != std::to_string(schema.version))
      throw InputError(where(line_number) + "schema `" + schema_text + "' of table `" + name +
                       "' is not known; this servodrift reads schema " + std::to_string(schema.version));
    table.producer = header_line("producer");
    table.parameters_sha256 = header_line("parameters-sha256");
    const std::string rows_text = header_line("rows");
    char *end = nullptr;
    const long declared_rows = std::strtol(rows_text.c_str(), &end, 10);
    if (rows_text.empty() || *end != '\0' || declared_rows < 0)
      throw InputError(where(line_number) + "`# rows' must give a row count, found `" + rows_text + "'");
    std::string columns_text = header_line("");
    while (columns_text.rfind("note ", 0) == 0 || columns_text == "note")
      {
        table.notes.push_back(trim(columns_text.substr(4)));
        columns_text = header_line("");
      }
    if (columns_text.rfind("columns", 0) != 0)
      throw InputError(where(line_number) + "expected `# columns ...' in the table header, found `# " +
                       columns_text.substr(0, 58) + "'");
    const std::vector<std::string> declared = split(trim(columns_text.substr(7)), ' ');
    const int columns_line = line_number;

    // Map every schema column to its position in the file; extra columns are ignored.
    std::vector<std::string> present;
    for (const auto &d : declared)
      if (!d.empty())
        present.push_back(d);
    std::vector<std::size_t> position(schema.columns.size());
    for (std::size_t c = 0; c < schema.columns.size(); ++c)
      {
        std::size_t k = 0;
        while (k < present.size() && present[k] != schema.columns[c].header())
          ++k;
        if (k == present.size())
          throw InputError(where(columns_line) + "column `" + schema.columns[c].header() + "' is missing");
        position[c] = k;
      }
    if (!std::getline(in, line))
      throw InputError(where(line_number + 1) + "file ends before the column header row (truncated table?)");
    ++line_number;
    {
      const auto header = split(trim(line), ',');
      if (header != present)
        throw InputError(where(line_number) + "the column header row does not match `# columns'");
    }

    while (std::getline(in, line))
      {
        ++line_number;
        line = trim(line);
        if (line.empty() || line[0] == '#')
          continue;
        const auto fields = split(line, ',');
        if (fields.size() != present.size())
          throw InputError(where(line_number) + std::to_string(fields.size()) + " fields where " +
                           std::to_string(present.size()) + " columns are declared (truncated or corrupted row)");
        std::vector<double> row(schema.columns.size());
        for (std::size_t c = 0; c < schema.columns.size(); ++c)
          {
            const std::string cell = trim(fields[position[c]]);
            const std::string at = path + ":" + std::to_string(line_number) + ":" + std::to_string(position[c] + 1) +
                                   ": `" + cell + "' in column `" + schema.columns[c].header() + "' ";
            char *cell_end = nullptr;
            const double value = std::strtod(cell.c_str(), &cell_end);
            if (cell.empty() || *cell_end != '\0')
              throw InputError(at + "is not a number");
            if (!std::isfinite(value))
              throw InputError(at + "is not finite");
            row[c] = value;
          }
        table.rows.push_back(std::move(row));
      }
    if (table.rows.empty())
      throw InputError(path + ": the table has no data rows");
    if (static_cast<long>(table.rows.size()) != declared_rows)
      throw InputError(path + ": " + std::to_string(table.rows.size()) + " data rows where the header declares " +
                       std::to_string(declared_rows) + " (truncated or corrupted table)");
    return table;
  }
} // namespace servodrift
