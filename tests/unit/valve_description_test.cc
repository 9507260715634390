// The valve description: defaults are RV-1, files and overrides apply in order, and every kind of
// bad input is refused with one line that names the entry.
#include "common/error.h"
#include "common/output_files.h"
#include "common/units.h"
#include "common/valve_description.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

#include <fstream>

using namespace servodrift;
using test::input_refusal;
using test::write_file;

TEST(ValveDescription, DefaultsAreRV1)
{
  const auto v = load_valve_description();
  EXPECT_EQ(v.source, "built-in RV-1");
  EXPECT_DOUBLE_EQ(v.operating.supply_pressure, 21e6);
  EXPECT_DOUBLE_EQ(v.operating.return_pressure, 0.4e6);
  EXPECT_DOUBLE_EQ(v.torque_motor.pivot_to_pole_distance, 14.8e-3);
  EXPECT_EQ(v.torque_motor.turns_per_coil, 1100u);
  EXPECT_DOUBLE_EQ(v.spring_tube.modulus_temperature_coefficient, 3.5e-4); // D5
  EXPECT_DOUBLE_EQ(v.pilot.null_gap, 40e-6);
  EXPECT_DOUBLE_EQ(v.spool.spring_rate, 1.0e3);  // C5
  EXPECT_DOUBLE_EQ(v.spool.spring_preload, 0.33); // C5
  EXPECT_EQ(v.fluid.viscosity_law, FluidParameters::ViscosityLaw::vogel); // D6
  EXPECT_EQ(v.offsets.nulling, OffsetParameters::Nulling::nulled_at_reference); // D8
  // issue 65: an aircraft valve's range, -55 to 135 degC, every 5 K; tables closer at the cold end
  EXPECT_EQ(v.sweeps.drift_temperatures.size(), 39u);
  EXPECT_DOUBLE_EQ(v.sweeps.drift_temperatures.front(), -55);
  EXPECT_DOUBLE_EQ(v.sweeps.drift_temperatures.back(), 135);
  EXPECT_EQ(v.sweeps.table_temperatures.size(), 12u);
  EXPECT_EQ(v.sweeps.deviation_angles.size(), 21u);
  EXPECT_NEAR(v.sweeps.deviation_angles.back(), 0.05 * units::degree, 1e-18);
  EXPECT_EQ(v.parameters_sha256.size(), 64u);
}

TEST(ValveDescription, FileThenOverridesInOrder)
{
  const std::string prm = write_file("a.prm", "subsection Pilot stage\n  set Null gap = 30e-6\nend\n");
  const auto v = load_valve_description(prm, {"Pilot stage/Null gap=35e-6", "Spool/Overlap = 10e-6"});
  EXPECT_DOUBLE_EQ(v.pilot.null_gap, 35e-6);
  EXPECT_DOUBLE_EQ(v.spool.overlap, 10e-6);
  EXPECT_EQ(v.source, prm);
}

TEST(ValveDescription, JsonEqualsPrm)
{
  const std::string prm = write_file("a.prm", "subsection Pilot stage\n  set Null gap = 30e-6\nend\n");
  const std::string json = write_file("a.json", R"({ "Pilot stage": { "Null gap": "30e-6" } })");
  EXPECT_EQ(load_valve_description(prm).parameters_sha256, load_valve_description(json).parameters_sha256);
  // the JSON that `servodrift params --format json' prints reads back to the same valve
  const std::string printed = write_file("p.json", print_parameters("", {"Spool/Overlap=12e-6"}, ParameterFormat::json));
  EXPECT_EQ(load_valve_description(printed).parameters_sha256,
            load_valve_description("", {"Spool/Overlap=12e-6"}).parameters_sha256);
}

TEST(ValveDescription, HashIgnoresOutputButNotPhysics)
{
  const auto a = load_valve_description("", {"Output/Directory=x"});
  const auto b = load_valve_description("", {"Output/Directory=y", "Output/Plots=false"});
  const auto c = load_valve_description("", {"Spool/Overlap=12e-6"});
  EXPECT_EQ(a.parameters_sha256, b.parameters_sha256);
  EXPECT_NE(a.parameters_sha256, c.parameters_sha256);
}

TEST(ValveDescription, RefusesMalformedFile)
{
  const std::string m = input_refusal([] { load_valve_description(write_file("m.prm", "subsection Pilot stage\n  set Null gap 3\nend\n")); });
  EXPECT_NE(m.find("m.prm:2"), std::string::npos) << m;
  const std::string unbalanced =
    input_refusal([] { load_valve_description(write_file("u.prm", "subsection Pilot stage\n  set Null gap = 3e-5\n")); });
  EXPECT_NE(unbalanced.find("u.prm"), std::string::npos) << unbalanced;
  const std::string json = input_refusal([] { load_valve_description(write_file("j.json", "{ \"Pilot stage\": {")); });
  EXPECT_NE(json.find("not valid JSON"), std::string::npos) << json;
  const std::string missing = input_refusal([] { load_valve_description("/nonexistent/valve.prm"); });
  EXPECT_NE(missing.find("/nonexistent/valve.prm"), std::string::npos) << missing;
  const std::string format = input_refusal([] { load_valve_description(write_file("v.txt", "x")); });
  EXPECT_NE(format.find("use a .prm or a .json file"), std::string::npos) << format;
}

TEST(ValveDescription, RefusesUnknownKey)
{
  const std::string in_file =
    input_refusal([] { load_valve_description(write_file("k.prm", "subsection Pilot stage\n  set Nul gap = 3e-5\nend\n")); });
  EXPECT_NE(in_file.find("k.prm:2"), std::string::npos) << in_file;
  EXPECT_NE(in_file.find("Nul gap"), std::string::npos) << in_file;
  EXPECT_NE(in_file.find("Pilot stage"), std::string::npos) << in_file;
  const std::string in_override = input_refusal([] { load_valve_description("", {"Pilot stage/Nul gap=3e-5"}); });
  EXPECT_NE(in_override.find("no entry `Nul gap' in subsection `Pilot stage'"), std::string::npos) << in_override;
  const std::string section = input_refusal([] { load_valve_description("", {"Pilot/Null gap=3e-5"}); });
  EXPECT_NE(section.find("no subsection `Pilot'"), std::string::npos) << section;
}

TEST(ValveDescription, RefusesValuesOutOfRange)
{
  // negative gap: the entry's own range, named with the allowed range
  const std::string negative = input_refusal([] { load_valve_description("", {"Pilot stage/Null gap=-1e-6"}); });
  EXPECT_NE(negative.find("Null gap"), std::string::npos) << negative;
  EXPECT_NE(negative.find("allowed: [Double 0...0.1"), std::string::npos) << negative;
  const std::string in_file =
    input_refusal([] { load_valve_description(write_file("n.prm", "subsection Pilot stage\n  set Null gap = -1e-6\nend\n")); });
  EXPECT_NE(in_file.find("n.prm:2: `Pilot stage/Null gap' = -1e-6 is not allowed"), std::string::npos) << in_file;
  // x0 larger than the nozzle radius (and than D_N/4)
  const std::string gap = input_refusal([] { load_valve_description("", {"Pilot stage/Null gap=0.25e-3"}); });
  EXPECT_NE(gap.find("`Pilot stage/Null gap'"), std::string::npos) << gap;
  EXPECT_NE(gap.find("D_N/4"), std::string::npos) << gap;
  // temperature outside the oil law's range
  const std::string hot = input_refusal([] { load_valve_description("", {"Sweeps/Drift temperatures=40, 160"}); });
  EXPECT_NE(hot.find("`Sweeps/Drift temperatures' contains 160 degC"), std::string::npos) << hot;
  const std::string cold = input_refusal([] { load_valve_description("", {"Sweeps/Table temperatures=-60, 40, 120"}); });
  EXPECT_NE(cold.find("-60 degC"), std::string::npos) << cold;
  // relations between entries
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Spring tube/Inner diameter=3.6e-3"}); }).find("Inner diameter"),
            std::string::npos);
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Operating conditions/Return pressure=22e6"}); }).find("Return pressure"),
            std::string::npos);
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Pilot stage/Land diameter=0.3e-3"}); }).find("Land diameter"),
            std::string::npos);
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Sweeps/Motor angles=-1.2, 0, 1.2"}); }).find("Motor angles"),
            std::string::npos);
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Sweeps/Table temperatures=40, 30, 120"}); }).find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(input_refusal([] { load_valve_description("", {"Torque motor/Armature height=10.3e-3"}); }).find("gap"),
            std::string::npos);
  EXPECT_NE(input_refusal([] {
              load_valve_description("", {"Offsets/Deviation target=hydraulic-null"});
            }).find("zero drift by construction"),
            std::string::npos);
}

TEST(ValveDescription, PrintedParameterFileReadsBack)
{
  const std::string text = print_parameters("", {}, ParameterFormat::prm);
  EXPECT_NE(text.find("subsection Operating conditions"), std::string::npos);
  const std::string path = write_file("rv1.prm", text);
  EXPECT_EQ(load_valve_description(path).parameters_sha256, load_valve_description().parameters_sha256);
  // every entry documents its unit as the last thing of its doc string
  const std::string full_md = print_parameters("", {}, ParameterFormat::markdown);
  const std::string md = full_md.substr(0, full_md.find("\n## Moved entries")); // the entries' table
  std::size_t rows = 0, pos = 0;
  while ((pos = md.find("\n| `", pos)) != std::string::npos)
    {
      const std::size_t end = md.find('\n', pos + 1);
      const std::string row = md.substr(pos + 1, end - pos - 1);
      // columns: subsection | entry | default | unit | allowed | meaning
      std::size_t bars = 0, k = 0, unit_start = 0;
      for (; k < row.size() && bars < 4; ++k)
        if (row[k] == '|' && ++bars == 4)
          unit_start = k + 1;
      const std::string unit = row.substr(unit_start, row.find('|', unit_start) - unit_start);
      EXPECT_GT(unit.find_first_not_of(' '), 0u) << row;
      EXPECT_NE(unit.find_first_not_of(' '), std::string::npos) << "no unit: " << row;
      ++rows;
      pos = end;
    }
  EXPECT_GT(rows, 100u);
}

TEST(ValveDescription, PrintedFileReadWithoutDealii)
{
  // A valve off the defaults in every kind of entry (number, integer, list, selection, boolean,
  // angle in degrees, subsection of a subsection): deal.II's print read by the lean reader (what the
  // FMU does with resources/parameters.prm) gives the values deal.II's reader gives.
  const std::vector<std::string> set = {"Operating conditions/Supply pressure=18e6", "Spool/Overlap=12e-6",
                                        "Fluid/Vogel B=600.25", "Offsets/Magnetic null=0.0125",
                                        "Asymmetry/Left null gap deviation=1.5e-6",
                                        "Sweeps/Drift temperatures=45, 60, 115", "Fits/Torque motor degrees=2, 3, 1",
                                        "Pilot stage/Model level=field", "Output/Plots=false",
                                        "Tolerances/Left orifice diameter/Standard deviation=2e-6"};
  const ValveDescription expected = load_valve_description("", set);
  const std::string path = write_file("printed.prm", print_parameters("", set, ParameterFormat::prm));
  const ValveDescription read = read_printed_valve_description(path);
  EXPECT_EQ(read.operating.supply_pressure, expected.operating.supply_pressure);
  EXPECT_EQ(read.spool.overlap, expected.spool.overlap);
  EXPECT_EQ(read.fluid.vogel_b, expected.fluid.vogel_b);
  EXPECT_EQ(read.offsets.magnetic_null, expected.offsets.magnetic_null);
  EXPECT_EQ(read.asymmetry.left.null_gap, expected.asymmetry.left.null_gap);
  EXPECT_EQ(read.sweeps.drift_temperatures, expected.sweeps.drift_temperatures);
  EXPECT_EQ(read.fits.torque_motor_degrees, expected.fits.torque_motor_degrees);
  EXPECT_EQ(read.pilot.model_level, expected.pilot.model_level);
  EXPECT_EQ(read.output.plots, expected.output.plots);
  ASSERT_EQ(read.tolerances.distributions.size(), expected.tolerances.distributions.size());
  for (std::size_t k = 0; k < read.tolerances.distributions.size(); ++k)
    EXPECT_EQ(read.tolerances.distributions[k].standard_deviation,
              expected.tolerances.distributions[k].standard_deviation);
  EXPECT_EQ(read.parameter_file, print_parameters("", set, ParameterFormat::prm));
}

TEST(ValveDescription, LeanReaderRefusesBrokenFiles)
{
  const std::string text = print_parameters("", {}, ParameterFormat::prm);
  // an entry removed, a number spoiled, an unbalanced subsection, a stray line: one line naming
  // the file and the entry
  std::string no_entry = text;
  const auto at = no_entry.find("set Overlap");
  no_entry.erase(at, no_entry.find('\n', at) - at);
  EXPECT_NE(input_refusal([&] { read_printed_valve_description(write_file("gone.prm", no_entry)); }).find("Spool/Overlap' is missing"),
            std::string::npos);
  std::string spoiled = text;
  const auto value = spoiled.find("= ", spoiled.find("set Overlap")) + 2;
  spoiled.insert(value, "x");
  const std::string m = input_refusal([&] { read_printed_valve_description(write_file("bad.prm", spoiled)); });
  EXPECT_NE(m.find("bad.prm: entry `Spool/Overlap'"), std::string::npos) << m;
  EXPECT_NE(m.find("not a finite number"), std::string::npos) << m;
  EXPECT_NE(input_refusal([&] { read_printed_valve_description(write_file("open.prm", "subsection Spool\n")); }).find("no `end'"),
            std::string::npos);
  EXPECT_NE(input_refusal([&] { read_printed_valve_description(write_file("stray.prm", "hello\n")); }).find("stray.prm:1:"),
            std::string::npos);
  EXPECT_NE(input_refusal([&] { read_printed_valve_description("/nonexistent/parameters.prm"); }).find("cannot be read"),
            std::string::npos);
}

TEST(ValveDescription, NullShiftSpecIsABandOverTemperature)
{
  // `Tolerances/Null-shift spec' per 55 K (the default, as catalogues quote it): 2 % of rated at
  // 55 K from T0 = 40 degC, 3.45 % at -55 degC and at 135 degC, none at T0 (where a null shift
  // below the null finder's 1 nA counts as none); constant; or a table, linear between its points
  // and held beyond them
  const auto v = load_valve_description();
  const auto &t = v.tolerances;
  ASSERT_EQ(t.null_shift_spec_form, ToleranceParameters::SpecForm::per_55_kelvin);
  EXPECT_DOUBLE_EQ(t.null_shift_limit(95, 40), 0.02);
  EXPECT_DOUBLE_EQ(t.null_shift_limit(-15, 40), 0.02);
  EXPECT_NEAR(t.null_shift_limit(-55, 40), 0.02 * 95 / 55, 1e-15);
  EXPECT_TRUE(t.within_null_shift_spec(5e-10, 40, 0.02, 40));
  EXPECT_FALSE(t.within_null_shift_spec(1e-7, 40, 0.02, 40));
  EXPECT_TRUE(t.within_null_shift_spec(-0.02 * 0.02 * 95 / 55, -55, 0.02, 40));
  EXPECT_EQ(t.null_shift_spec_text(40), "2 % of rated per 55 K from 40 degC");
  const auto constant = load_valve_description("", {"Tolerances/Null-shift spec form=constant"});
  EXPECT_DOUBLE_EQ(constant.tolerances.null_shift_limit(40, 40), 0.02);
  const auto table = load_valve_description(
    "", {"Tolerances/Null-shift spec form=table", "Tolerances/Null-shift spec table=-60: 4, 40: 0.5, 140: 3"});
  EXPECT_DOUBLE_EQ(table.tolerances.null_shift_limit(-10, 40), 0.0225);
  EXPECT_DOUBLE_EQ(table.tolerances.null_shift_limit(90, 40), 0.0175);
  EXPECT_DOUBLE_EQ(table.tolerances.null_shift_limit(40, 40), 0.005);
  EXPECT_NE(table.tolerances.null_shift_spec_text(40).find("4 % at -60 degC"), std::string::npos);
}

TEST(ValveDescription, RefusesANullShiftSpecTableThatIsBrokenOrShort)
{
  const auto refused = [](const std::string &table) {
    return input_refusal([&] {
      load_valve_description("", {"Tolerances/Null-shift spec form=table", "Tolerances/Null-shift spec table=" + table});
    });
  };
  // each refusal names the entry and what is allowed
  for (const std::string &m : {refused("-55: 4, 40 0.5, 135: 4"), refused("-55: 4, 40: x, 135: 4")})
    {
      EXPECT_NE(m.find("`Tolerances/Null-shift spec table'"), std::string::npos) << m;
      EXPECT_NE(m.find("allowed: `T: allowed' pairs"), std::string::npos) << m;
    }
  EXPECT_NE(refused("-55: 4, -55: 3, 135: 4").find("strictly increasing"), std::string::npos);
  EXPECT_NE(refused("-55: 4, 40: 120, 135: 4").find("allowed: 0 to 100 %"), std::string::npos);
  EXPECT_NE(refused("0: 4, 135: 4").find("not the drift temperatures' -55 to 135 degC"), std::string::npos);
  EXPECT_NE(refused("0: 4").find("needs at least 2"), std::string::npos);
}
