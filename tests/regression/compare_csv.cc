// compare_csv [--ignore COLUMN]... REFERENCE RESULT [RELATIVE [FLOOR]]: compares two servodrift CSV
// outputs cell by cell, ignoring '#' header lines (they carry the producer's git revision) and the
// columns named by --ignore (by their header, e.g. `wall_time[s]': what a run cannot reproduce).
// Text cells must match exactly; a number b matches its reference a if
// |b - a| <= RELATIVE |a| + FLOOR max|column of a|.
// Defaults: RELATIVE = 1e-6, FLOOR = 1e-9 (the static solver's root tolerances are 1e-10 of the
// pressure span and 1e-13 of the angle bracket; deviations are differences of such results).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <set>
#include <string>
#include <vector>

namespace
{
  std::vector<std::vector<std::string>> read(const char *path)
  {
    std::ifstream in(path);
    if (!in)
      {
        std::cerr << path << ": cannot open\n";
        std::exit(2);
      }
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream s(line);
        while (std::getline(s, cell, ','))
          cells.push_back(cell);
        if (!line.empty() && line.back() == ',')
          cells.emplace_back();
        rows.push_back(cells);
      }
    return rows;
  }

  bool number(const std::string &s, double &v)
  {
    char *end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0';
  }
} // namespace

int main(int argc, char **argv)
{
  std::set<std::string> ignored;
  std::vector<const char *> positional;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--ignore" && i + 1 < argc)
      ignored.insert(argv[++i]);
    else
      positional.push_back(argv[i]);
  if (positional.size() < 2)
    {
      std::cerr << "usage: compare_csv [--ignore COLUMN]... REFERENCE RESULT [RELATIVE [FLOOR]]\n";
      return 2;
    }
  const double relative = positional.size() > 2 ? std::atof(positional[2]) : 1e-6,
               floor = positional.size() > 3 ? std::atof(positional[3]) : 1e-9;
  const auto a = read(positional[0]), b = read(positional[1]);
  if (a.empty())
    {
      std::cerr << positional[0] << ": no rows\n";
      return 1;
    }
  for (const auto &name : ignored)
    if (std::find(a[0].begin(), a[0].end(), name) == a[0].end())
      {
        std::cerr << "--ignore " << name << ": no such column in " << positional[0] << "\n";
        return 2;
      }
  if (a.size() != b.size())
    {
      std::cerr << "row count " << b.size() << " differs from the reference's " << a.size() << "\n";
      return 1;
    }
  std::vector<double> column_max;
  for (const auto &row : a)
    for (std::size_t c = 0; c < row.size(); ++c)
      {
        double v;
        column_max.resize(std::max(column_max.size(), row.size()), 0.0);
        if (number(row[c], v))
          column_max[c] = std::max(column_max[c], std::abs(v));
      }
  int failures = 0;
  for (std::size_t r = 0; r < a.size(); ++r)
    {
      if (a[r].size() != b[r].size())
        {
          std::cerr << "row " << r + 1 << ": " << b[r].size() << " cells, reference " << a[r].size() << "\n";
          return 1;
        }
      for (std::size_t c = 0; c < a[r].size(); ++c)
        {
          if (ignored.count(a[0][c]))
            continue;
          double x, y;
          const bool ok = number(a[r][c], x) && number(b[r][c], y) ?
                            std::abs(y - x) <= relative * std::abs(x) + floor * column_max[c] :
                            a[r][c] == b[r][c];
          if (!ok && ++failures <= 10)
            std::cerr << "row " << r + 1 << " column " << c + 1 << " (" << a[0][c] << "): " << b[r][c]
                      << ", reference " << a[r][c] << "\n";
        }
    }
  if (failures)
    std::cerr << failures << " cells differ\n";
  else
    std::cout << "ok: " << a.size() << " rows match\n";
  return failures ? 1 : 0;
}
