// Moved entries (common/parameters/renamed_entries.h): a description that names an entry by its
// old path, in a PRM file, a JSON file or a --set, reads as the same valve as one that names it by
// its new path, with one deprecation warning line per use; a file that sets both names, or a value
// outside the entry's range, is refused with one line naming the file, the line and the entry.
#include "common/error.h"
#include "common/parameter_input.h"
#include "common/parameters/renamed_entries.h"
#include "common/valve_description.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <set>
#include <sstream>

using namespace servodrift;
using test::input_refusal;
using test::write_file;

namespace
{
  bool declared(const boost::property_tree::ptree &tree, const std::string &path)
  {
    return tree.get_child_optional(boost::property_tree::ptree::path_type(path, '/')).has_value();
  }
} // namespace

// The table is data the readers trust: every new path is a declared entry, no old path is one, and
// no entry moved twice.
TEST(RenamedEntries, NewPathsAreDeclaredOldOnesAreNot)
{
  std::istringstream json(print_parameters("", {}, ParameterFormat::json));
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(json, tree);
  std::set<std::string> old_paths;
  for (const auto &e : renamed_entries())
    {
      EXPECT_TRUE(declared(tree, e.new_path + "/value")) << e.new_path;
      EXPECT_FALSE(declared(tree, e.old_path + "/value")) << e.old_path;
      EXPECT_TRUE(old_paths.insert(e.old_path).second) << e.old_path << " listed twice";
      EXPECT_EQ(renamed_entry(e.old_path), &e);
      EXPECT_EQ(renamed_entry(e.new_path), nullptr);
    }
  EXPECT_EQ(renamed_entries().size(), 28u); // "Pilot stage" split by concern
}

// An old parameter file, a JSON file and --set overrides with the old names give the valve of the
// new names (the same hash of the values), with one warning line per entry naming where it was.
TEST(RenamedEntries, OldNamesReadAsTheNewOnes)
{
  const std::string current =
    write_file("current.prm", "subsection Pilot stage\n"
                         "  subsection Field mesh\n    set Resolution = 0.75\n  end\n"
                         "  subsection Time average\n    set Steps = 300\n    set Uncertainty limit = 0.02\n  end\n"
                         "  subsection Bore sensitivity\n    set Tables = on\n  end\n"
                         "  subsection Reduced order\n    set Nozzle law = paper-fit\n  end\n"
                         "end\n");
  // a continued line and a new-style subsection between old entries
  const std::string old_prm =
    write_file("old.prm", "subsection Pilot stage\n"
                     "  set Field mesh resolution = 0.75   # old\n"
                     "  set Field time steps = \\\n      300\n"
                     "  subsection Field solution\n    set Cavitation = true\n  end\n"
                     "  set Field time average uncertainty limit = 0.02\n"
                     "  set Bore sensitivity = on\n"
                     "  set Nozzle law = paper-fit\n"
                     "end\n");
  const std::string old_json =
    write_file("old.json", R"({"Pilot stage": {"Field mesh resolution": "0.75", "Field time steps": {"value": "300"},
                          "Field time average uncertainty limit": 0.02, "Bore sensitivity": "on",
                          "Nozzle law": "paper-fit"}})");
  const std::string expected = load_valve_description(current).parameters_sha256;

  testing::internal::CaptureStderr();
  const ValveDescription from_prm = load_valve_description(old_prm);
  const std::string prm_warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(from_prm.parameters_sha256, expected);
  EXPECT_DOUBLE_EQ(from_prm.pilot.field_mesh.resolution, 0.75);
  EXPECT_EQ(from_prm.pilot.time_average.steps, 300u);
  EXPECT_EQ(from_prm.pilot.bore_sensitivity.tables, BoreSensitivityParameters::Tables::on);
  EXPECT_NE(prm_warnings.find(old_prm + ":2: `Pilot stage/Field mesh resolution' is deprecated; it is now `Pilot "
                                        "stage/Field mesh/Resolution'"),
            std::string::npos)
    << prm_warnings;
  EXPECT_NE(prm_warnings.find(old_prm + ":3: `Pilot stage/Field time steps'"), std::string::npos) << prm_warnings;
  EXPECT_NE(prm_warnings.find(old_prm + ":8: `Pilot stage/Field time average uncertainty limit'"), std::string::npos)
    << prm_warnings;
  EXPECT_EQ(std::count(prm_warnings.begin(), prm_warnings.end(), '\n'), 5) << prm_warnings;

  testing::internal::CaptureStderr();
  EXPECT_EQ(load_valve_description(old_json).parameters_sha256, expected);
  const std::string json_warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(std::count(json_warnings.begin(), json_warnings.end(), '\n'), 5) << json_warnings;

  testing::internal::CaptureStderr();
  EXPECT_EQ(load_valve_description("", {"Pilot stage/Field mesh resolution=0.75", "Pilot stage/Field time steps=300",
                                        "Pilot stage/Field time average uncertainty limit = 0.02",
                                        "Pilot stage/Bore sensitivity=on", "Pilot stage/Nozzle law=paper-fit"})
              .parameters_sha256,
            expected);
  const std::string set_warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(set_warnings.find("--set \"Pilot stage/Bore sensitivity=on\": `Pilot stage/Bore sensitivity' is "
                              "deprecated; it is now `Pilot stage/Bore sensitivity/Tables'"),
            std::string::npos)
    << set_warnings;

  // a free parameter of a calibration named by its old path
  testing::internal::CaptureStderr();
  EXPECT_EQ(current_entry_path("Pilot stage/Nozzle discharge coefficient", "--free"),
            "Pilot stage/Reduced order/Nozzle discharge coefficient");
  EXPECT_EQ(current_entry_path("Pilot stage/Null gap", "--free"), "Pilot stage/Null gap");
  EXPECT_NE(testing::internal::GetCapturedStderr().find("--free: `Pilot stage/Nozzle discharge coefficient'"),
            std::string::npos);
}

// One entry under both names, a value outside the range under the old name, an old name in an
// included file: each refused with one line naming file, line and entry.
TEST(RenamedEntries, RefusesAmbiguousOrBadOldEntries)
{
  const std::string both = input_refusal([] {
    load_valve_description(write_file("both.prm", "subsection Pilot stage\n  set Field time steps = 300\n"
                                             "  subsection Time average\n    set Steps = 400\n  end\nend\n"));
  });
  EXPECT_NE(both.find("both.prm:2: `Pilot stage/Field time steps' is the old name of `Pilot stage/Time "
                      "average/Steps', which the file sets too; keep one"),
            std::string::npos)
    << both;

  const std::string range = input_refusal(
    [] { load_valve_description(write_file("range.prm", "subsection Pilot stage\n\n  set Field time steps = 3\nend\n")); });
  EXPECT_NE(range.find("range.prm:3: `Pilot stage/Field time steps' (now `Pilot stage/Time average/Steps') = 3 is "
                       "not allowed; allowed: [Integer range 20...10000000 (inclusive)]"),
            std::string::npos)
    << range;

  const std::string json = input_refusal(
    [] { load_valve_description(write_file("range.json", R"({"Pilot stage": {"Field cavitation": "perhaps"}})")); });
  EXPECT_NE(json.find("range.json: `Pilot stage/Field cavitation' (now `Pilot stage/Field solution/Cavitation') = "
                      "perhaps is not allowed"),
            std::string::npos)
    << json;

  const std::string inner = write_file("inner.prm", "subsection Pilot stage\n  set Field cavitation = false\nend\n");
  const std::string outer = write_file("outer.prm", "include " + inner + "\n");
  const std::string included = input_refusal([&] { load_valve_description(outer); });
  EXPECT_NE(included.find(inner + ":2: `Pilot stage/Field cavitation' is now `Pilot stage/Field solution/Cavitation'"),
            std::string::npos)
    << included;
}

// A retired entry (no longer read) in a PRM file, a JSON file or a --set: the valve reads as one
// without it, with one warning line naming where it was and why; as a calibration's free parameter,
// or in an included file (read as written), it is refused with one line.
TEST(RenamedEntries, RetiredEntriesAreIgnoredWithAWarning)
{
  ASSERT_FALSE(retired_entries().empty());
  const RetiredEntry &gone = retired_entries().front();
  std::istringstream json(print_parameters("", {}, ParameterFormat::json));
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(json, tree);
  EXPECT_FALSE(declared(tree, gone.path + "/value")) << gone.path;
  EXPECT_EQ(renamed_entry(gone.path), nullptr);

  const std::string section = gone.path.substr(0, gone.path.find('/')), key = gone.path.substr(gone.path.find('/') + 1);
  const std::string expected = load_valve_description("").parameters_sha256;
  const std::string prm = write_file("retired.prm", "subsection " + section + "\n  set " + key + " = 0.02\nend\n");
  const std::string js = write_file("retired.json", "{\"" + section + "\": {\"" + key + "\": \"0.02\"}}");
  for (const auto &[source, where] : {std::pair{prm, prm + ":2"}, std::pair{js, js}})
    {
      testing::internal::CaptureStderr();
      EXPECT_EQ(load_valve_description(source).parameters_sha256, expected) << source;
      const std::string warnings = testing::internal::GetCapturedStderr();
      EXPECT_NE(warnings.find(where + ": `" + gone.path + "' is no longer read ("), std::string::npos) << warnings;
      EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
    }
  testing::internal::CaptureStderr();
  EXPECT_EQ(load_valve_description("", {gone.path + "=0.02"}).parameters_sha256, expected);
  const std::string set_warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(set_warnings.find("`" + gone.path + "' is no longer read"), std::string::npos) << set_warnings;

  EXPECT_THROW(current_entry_path(gone.path, "--free"), InputError);
  const std::string included = input_refusal([&] {
    load_valve_description(write_file("includes.prm", "include " + prm + "\n"));
  });
  EXPECT_NE(included.find("is no longer read"), std::string::npos) << included;
}
