#include "common/table_formats.h"

#include "common/error.h"
#include "common/output_files.h"

#include <matio.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace servodrift
{
  GriddedData gridded(const Table &table)
  {
    const TableSchema &schema = table.schema();
    GriddedData g;
    g.name = table.name();
    g.description = "servodrift table " + table.name() + " (" + table.producer + ")";
    const std::size_t n_axes = schema.n_axes;
    std::vector<std::map<double, std::size_t>> index(n_axes);
    for (std::size_t a = 0; a < n_axes; ++a)
      {
        std::vector<double> v = table.column(schema.columns[a].name);
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
        for (std::size_t k = 0; k < v.size(); ++k)
          index[a][v[k]] = k;
        g.axes.push_back({schema.columns[a], v});
      }
    std::size_t size = 1;
    for (const auto &a : g.axes)
      size *= a.values.size();
    if (size != table.rows.size())
      throw std::runtime_error(table.name() + ": the rows are not a full grid of its axes");
    for (std::size_t c = n_axes; c < schema.columns.size(); ++c)
      g.quantities.push_back({schema.columns[c], std::vector<double>(size)});
    for (const auto &row : table.rows)
      {
        std::size_t at = 0, stride = 1;
        for (std::size_t a = 0; a < n_axes; ++a)
          {
            at += stride * index[a].at(row[a]);
            stride *= g.axes[a].values.size();
          }
        for (std::size_t c = n_axes; c < row.size(); ++c)
          g.quantities[c - n_axes].values[at] = row[c];
      }
    return g;
  }

  namespace
  {
    struct MatFree
    {
      void operator()(matvar_t *v) const { Mat_VarFree(v); }
    };
    using MatVariable = std::unique_ptr<matvar_t, MatFree>;

    MatVariable mat_array(const std::vector<double> &values, std::vector<std::size_t> dims)
    {
      return MatVariable(Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, static_cast<int>(dims.size()), dims.data(),
                                       const_cast<double *>(values.data()), 0));
    }

    MatVariable mat_text(const std::string &text)
    {
      std::size_t dims[2] = {1, text.size()};
      return MatVariable(Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UTF8, 2, dims, const_cast<char *>(text.data()), 0));
    }
  } // namespace

  void write_mat(const std::string &path, const std::vector<GriddedData> &data)
  {
    const std::string temporary = temporary_beside(path);
    mat_t *file = Mat_CreateVer(temporary.c_str(), "servodrift coefficient tables", MAT_FT_MAT5);
    if (!file)
      throw InputError(temporary + ": cannot be written");
    bool ok = true;
    for (const auto &g : data)
      {
        std::vector<std::string> names;
        for (const auto &a : g.axes)
          names.push_back(a.column.name);
        for (const auto &q : g.quantities)
          names.push_back(q.column.name);
        names.push_back("units");
        names.push_back("description");
        std::vector<const char *> fields;
        for (const auto &n : names)
          fields.push_back(n.c_str());
        fields.push_back(nullptr);
        std::size_t one[2] = {1, 1};
        MatVariable s(Mat_VarCreateStruct2(g.name.c_str(), 2, one, fields.data()));
        std::vector<std::size_t> dims;
        std::string units;
        for (const auto &a : g.axes)
          {
            Mat_VarSetStructFieldByName(s.get(), a.column.name.c_str(), 0,
                                        mat_array(a.values, {a.values.size(), 1}).release());
            dims.push_back(a.values.size());
            units += (units.empty() ? "" : " ") + a.column.header();
          }
        if (dims.size() == 1)
          dims.push_back(1);
        for (const auto &q : g.quantities)
          {
            Mat_VarSetStructFieldByName(s.get(), q.column.name.c_str(), 0, mat_array(q.values, dims).release());
            units += " " + q.column.header();
          }
        Mat_VarSetStructFieldByName(s.get(), "units", 0, mat_text(units).release());
        Mat_VarSetStructFieldByName(s.get(), "description", 0, mat_text(g.description).release());
        ok = ok && Mat_VarWrite(file, s.get(), MAT_COMPRESSION_NONE) == 0;
      }
    ok = Mat_Close(file) == 0 && ok;
    if (!ok)
      {
        std::filesystem::remove(temporary);
        throw InputError(path + ": the MAT file could not be written");
      }
    install_file(temporary, path);
  }

  namespace
  {
    /// The shortest of %.15g, %.16g, %.17g that reads back as `v'
    std::string number(double v)
    {
      char text[32];
      for (int digits : {15, 16, 17})
        {
          std::snprintf(text, sizeof(text), "%.*g", digits, v);
          if (std::strtod(text, nullptr) == v)
            break;
        }
      return text;
    }

    /// A CombiTable2Ds matrix of `q' over axes a (rows) and b (columns), at offset `at' with strides
    void table_2d(std::ostream &out, const std::string &name, const GriddedData::Axis &a, const GriddedData::Axis &b,
                  const std::vector<double> &values, std::size_t at)
    {
      out << "double " << name << "(" << a.values.size() + 1 << "," << b.values.size() + 1 << ")\n0";
      for (double v : b.values)
        out << " " << number(v);
      out << "\n";
      for (std::size_t i = 0; i < a.values.size(); ++i)
        {
          out << number(a.values[i]);
          for (std::size_t j = 0; j < b.values.size(); ++j)
            out << " " << number(values[at + i + a.values.size() * j]);
          out << "\n";
        }
    }
  } // namespace

  void write_modelica(const std::string &path, const std::vector<GriddedData> &data)
  {
    std::ostringstream out;
    out << "#1\n# servodrift coefficient tables as Modelica text tables (CombiTable1Ds, CombiTable2Ds); SI units\n";
    for (const auto &g : data)
      {
        out << "\n# " << g.description << "\n";
        if (g.axes.size() == 1)
          {
            out << "# columns: " << g.axes[0].column.header();
            for (const auto &q : g.quantities)
              out << " " << q.column.header();
            out << "\ndouble " << g.name << "(" << g.axes[0].values.size() << "," << g.quantities.size() + 1 << ")\n";
            for (std::size_t i = 0; i < g.axes[0].values.size(); ++i)
              {
                out << number(g.axes[0].values[i]);
                for (const auto &q : g.quantities)
                  out << " " << number(q.values[i]);
                out << "\n";
              }
            continue;
          }
        const std::size_t first = g.axes.size() - 2; // the two last axes span each matrix
        const auto &a = g.axes[first], &b = g.axes[first + 1];
        const std::size_t n_outer = g.axes.size() == 3 ? g.axes[0].values.size() : 1;
        for (const auto &q : g.quantities)
          for (std::size_t k = 0; k < n_outer; ++k)
            {
              std::string name = g.name + "_" + q.column.name;
              out << "# " << q.column.header() << " over " << a.column.header() << " (rows) and " << b.column.header()
                  << " (columns)";
              if (g.axes.size() == 3)
                {
                  name += "_" + std::to_string(k + 1);
                  out << " at " << g.axes[0].column.header() << " = " << number(g.axes[0].values[k]);
                }
              out << "\n";
              // with three axes, axis 0 is fastest: the 2D slice k has strides n0 and n0 n1
              if (g.axes.size() == 3)
                {
                  const std::size_t n0 = g.axes[0].values.size();
                  std::vector<double> slice(a.values.size() * b.values.size());
                  for (std::size_t i = 0; i < a.values.size(); ++i)
                    for (std::size_t j = 0; j < b.values.size(); ++j)
                      slice[i + a.values.size() * j] = q.values[k + n0 * (i + a.values.size() * j)];
                  table_2d(out, name, a, b, slice, 0);
                }
              else
                table_2d(out, name, a, b, q.values, 0);
            }
      }
    write_file_atomically(path, out.str());
  }
} // namespace servodrift
