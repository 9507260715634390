#include "tests/support/core_support.h"

#include "common/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace servodrift::test
{
  namespace
  {
    std::vector<std::string> &created_directories()
    {
      static std::vector<std::string> directories;
      return directories;
    }
  } // namespace

  std::string temporary_directory()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "servodrift-test-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error("mkdtemp failed");
    created_directories().push_back(pattern);
    return pattern;
  }

  std::string write_file(const std::string &name, const std::string &text)
  {
    const std::string path = temporary_directory() + "/" + name;
    std::ofstream(path) << text;
    return path;
  }

  std::string input_refusal(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        const std::string m = e.what();
        EXPECT_EQ(m.find('\n'), std::string::npos) << "not one line: " << m;
        return m;
      }
    ADD_FAILURE() << "no InputError";
    return "";
  }

  void remove_temporary_directories()
  {
    std::error_code ignored; // a directory a test removed itself is fine
    for (const std::string &directory : created_directories())
      std::filesystem::remove_all(directory, ignored);
    created_directories().clear();
  }

  ValveDescription rv1() { return read_printed_valve_description(SERVODRIFT_SOURCE_DIR "/examples/rv1.prm"); }

  std::string number(double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.6g", value);
    return buffer;
  }

  double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }
} // namespace servodrift::test
