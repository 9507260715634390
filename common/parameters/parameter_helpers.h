#pragma once
// Helpers for the .cc files that declare and parse parameters. This header includes deal.II's
// ParameterHandler; include it only from .cc files (keeps deal.II out of our headers).
#include "common/parameters/parameter_source.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace servodrift::parameters
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  /// Comma-separated list of doubles, each within [min, max].
  Patterns::List double_list(double min, double max, unsigned int min_elements = 1);
  /// Comma-separated list of integers, each within [min, max].
  Patterns::List integer_list(int min, int max, unsigned int min_elements = 1,
                              unsigned int max_elements = Patterns::List::max_int_value);

  /// deal.II's handler as the structs' ParameterSource: numbers through deal.II's own conversions
  /// (its patterns checked them as they were read).
  class HandlerSource : public ParameterSource
  {
  public:
    explicit HandlerSource(ParameterHandler &prm)
      : prm(prm)
    {}
    void enter_subsection(const std::string &name) override
    {
      prm.enter_subsection(name);
      current.push_back(name);
    }
    void leave_subsection() override
    {
      prm.leave_subsection();
      current.pop_back();
    }
    std::string get(const std::string &key) const override { return prm.get(key); }
    double get_double(const std::string &key) const override { return prm.get_double(key); }
    long get_integer(const std::string &key) const override { return prm.get_integer(key); }
    bool get_bool(const std::string &key) const override { return prm.get_bool(key); }

  protected:
    std::string path_of(const std::string &key) const override
    {
      std::string path;
      for (const auto &s : current)
        path += s + "/";
      return path + key;
    }

  private:
    ParameterHandler &prm;
    std::vector<std::string> current;
  };
} // namespace servodrift::parameters
