#include "tests/support/test_support.h"

#include "common/stage_output.h"
#include "flow/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

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

  void remove_temporary_directories()
  {
    std::error_code ignored; // a directory a test removed itself is fine
    for (const std::string &directory : created_directories())
      std::filesystem::remove_all(directory, ignored);
    created_directories().clear();
  }

  ValveDescription valve(std::vector<std::string> overrides)
  {
    // the reduced-order torque motor, spring tube and pilot stage unless a test asks for the field
    // level (the system-model tests compare with model.md's closed-form figures)
    overrides.insert(overrides.begin(), "Pilot stage/Model level=reduced-order");
    overrides.insert(overrides.begin(), "Torque motor/Model level=reduced-order");
    overrides.insert(overrides.begin(), "Spring tube/Model level=reduced-order");
    // the dynamics only where a test asks for them (its checks need the torque table to reach the
    // nozzle contacts and the sine amplitudes, which some static tests narrow on purpose)
    overrides.insert(overrides.begin(), "Dynamics/Enabled=false");
    overrides.push_back("Output/Directory=" + temporary_directory());
    overrides.push_back("Output/Progress=none");
    return load_valve_description("", overrides);
  }

  std::string write_reduced_order_tables(const ValveDescription &v)
  {
    magnetics::run(v);
    structure::run(v);
    flow::run(v);
    return tables_directory(v);
  }

  std::string number(double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.6g", value);
    return buffer;
  }

  double relative(double a, double b)
  {
    return std::abs(a - b) / std::abs(b);
  }
} // namespace servodrift::test
