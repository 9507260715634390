// Coefficient tables: round trip, and every refusal names file, line (and column).
#include "common/error.h"
#include "common/output_files.h"
#include "common/table.h"
#include "tests/support/core_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace servodrift;

namespace
{
  Table sample()
  {
    Table t(schemas::spring_tube);
    t.producer = "servodrift test";
    t.parameters_sha256 = "abc";
    t.rows = {{40, 21.44, 0}, {80, 21.1812345678901, 0}, {120, -1.5e-300, 1}};
    return t;
  }

  std::string write_text(const std::string &text)
  {
    const std::string path = test::temporary_directory() + "/spring_tube.csv";
    std::ofstream(path) << text;
    return path;
  }

  std::string refusal(const std::string &text, const std::string &name = "spring_tube")
  {
    const std::string path = write_text(text);
    try
      {
        Table::read(path, name);
      }
    catch (const InputError &e)
      {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind(path, 0), 0u) << "message does not start with the file: " << m;
        return m.substr(path.size());
      }
    ADD_FAILURE() << "no refusal";
    return "";
  }

  std::string replace(std::string s, const std::string &from, const std::string &to)
  {
    s.replace(s.find(from), from.size(), to);
    return s;
  }
} // namespace

TEST(Table, RoundTripKeepsTwelveDigits)
{
  const Table t = sample();
  const std::string path = write_text(t.to_csv());
  const Table back = Table::read(path, "spring_tube");
  EXPECT_EQ(back.producer, t.producer);
  EXPECT_EQ(back.parameters_sha256, "abc");
  ASSERT_EQ(back.rows.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_LE(std::abs(back.rows[r][c] - t.rows[r][c]), 1e-12 * std::abs(t.rows[r][c])) << r << "," << c;
  EXPECT_EQ(back.to_csv(), t.to_csv()); // and the text is stable
}

TEST(Table, HeaderIsReadableAndStamped)
{
  const std::string text = sample().to_csv();
  EXPECT_EQ(text.rfind("# servodrift-table spring_tube\n# schema 1\n# producer servodrift test\n", 0), 0u);
  EXPECT_NE(text.find("# columns temperature[degC] stiffness[N*m/rad] flag[1]\n"), std::string::npos);
  EXPECT_NE(text.find("\ntemperature[degC],stiffness[N*m/rad],flag[1]\n"), std::string::npos);
}

TEST(Table, NotesSurviveTheRoundTripAndAMissingColumnsLineIsRefused)
{
  Table t = sample();
  t.notes = {"mesh resolution 1: C_dn within 3 %", "second note"};
  const std::string text = t.to_csv();
  EXPECT_NE(text.find("# rows 3\n# note mesh resolution 1: C_dn within 3 %\n# note second note\n# columns "),
            std::string::npos)
    << text;
  const Table back = Table::read(write_text(text), "spring_tube");
  EXPECT_EQ(back.notes, t.notes);
  EXPECT_EQ(back.to_csv(), text);
  EXPECT_NE(refusal(replace(text, "# columns", "# colons")).find(":8: expected `# columns ...' in the table header"),
            std::string::npos)
    << refusal(replace(text, "# columns", "# colons"));
}

TEST(Table, RefusesWrongTableAndUnknownSchema)
{
  const std::string good = sample().to_csv();
  EXPECT_NE(refusal(good, "torque_motor").find(":1: table `spring_tube' where a `torque_motor' table was expected"),
            std::string::npos);
  EXPECT_NE(refusal(replace(good, "# schema 1", "# schema 7")).find(":2: schema `7' of table `spring_tube' is not known"),
            std::string::npos);
  EXPECT_NE(refusal("hello\n").find(":1: expected `# servodrift-table"), std::string::npos);
}

TEST(Table, RefusesMissingColumn)
{
  std::string text = sample().to_csv();
  text = replace(text, " stiffness[N*m/rad]", "");
  text = replace(text, ",stiffness[N*m/rad]", "");
  EXPECT_NE(refusal(text).find(":6: column `stiffness[N*m/rad]' is missing"), std::string::npos) << refusal(text);
}

TEST(Table, RefusesNonNumericAndNonFiniteCells)
{
  const std::string good = sample().to_csv();
  const std::string word = refusal(replace(good, "80,21.1812345679", "80,abc"));
  EXPECT_NE(word.find(":9:2: `abc' in column `stiffness[N*m/rad]' is not a number"), std::string::npos) << word;
  const std::string nan = refusal(replace(good, "80,21.1812345679", "80,nan"));
  EXPECT_NE(nan.find(":9:2: `nan' in column `stiffness[N*m/rad]' is not finite"), std::string::npos) << nan;
  const std::string inf = refusal(replace(good, "40,21.44", "inf,21.44"));
  EXPECT_NE(inf.find(":8:1: `inf' in column `temperature[degC]' is not finite"), std::string::npos) << inf;
  const std::string empty = refusal(replace(good, "40,21.44", ",21.44"));
  EXPECT_NE(empty.find(":8:1: `' in column `temperature[degC]' is not a number"), std::string::npos) << empty;
}

TEST(Table, RefusesTruncatedOrCorruptedRows)
{
  const std::string good = sample().to_csv();
  // cut in the middle of the last row
  const std::string cut = refusal(good.substr(0, good.size() - 6));
  EXPECT_NE(cut.find(":10: 2 fields where 3 columns are declared"), std::string::npos) << cut;
  // cut at a row boundary: only the row count notices
  const std::string lost = refusal(good.substr(0, good.rfind("120,")));
  EXPECT_NE(lost.find("2 data rows where the header declares 3"), std::string::npos) << lost;
  // cut inside the header
  EXPECT_NE(refusal(good.substr(0, good.find("# rows"))).find(":5: file ends inside the header"), std::string::npos);
  EXPECT_NE(refusal(replace(good, "# rows 3", "# rows x")).find("`# rows' must give a row count"), std::string::npos);
}

TEST(Table, WriteIsAtomic)
{
  const std::string dir = test::temporary_directory();
  sample().write(dir + "/spring_tube.csv");
  EXPECT_NO_THROW(Table::read(dir + "/spring_tube.csv", "spring_tube"));
  // no temporary file left behind
  std::size_t files = 0;
  for (const auto &e : std::filesystem::directory_iterator(dir))
    files += e.is_regular_file();
  EXPECT_EQ(files, 1u);
  EXPECT_THROW(sample().write("/nonexistent-dir/x.csv"), InputError);
}

TEST(Table, RefusesToWriteNonFiniteValues)
{
  Table t = sample();
  t.rows[1][1] = std::nan("");
  EXPECT_THROW(t.to_csv(), std::logic_error);
}
