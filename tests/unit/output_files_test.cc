// Outputs (issue 24): a run's files as one transaction, and no non-finite number in a result file.
#include "common/csv.h"
#include "common/output_files.h"
#include "tests/support/core_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>

using namespace servodrift;
namespace fs = std::filesystem;

namespace
{
  std::string content(const fs::path &p)
  {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /// A directory with an old result and an unrelated file, as a previous run leaves it.
  fs::path previous_run()
  {
    const fs::path dir = fs::path(test::temporary_directory()) / "out";
    fs::remove_all(dir);
    fs::create_directories(dir / "tables");
    std::ofstream(dir / "tables" / "old.csv") << "old\n";
    std::ofstream(dir / "notes.txt") << "mine\n";
    return dir;
  }

  /// The run's writes: one file replaced, one new file in a new directory, one written twice.
  void run_writes(const fs::path &dir)
  {
    write_file_atomically((dir / "tables" / "old.csv").string(), "new\n");
    prepare_output_directory((dir / "system" / "plots").string());
    write_file_atomically((dir / "system" / "plots" / "a.dat").string(), "1\n");
    write_file_atomically((dir / "tables" / "twice.csv").string(), "first\n");
    write_file_atomically((dir / "tables" / "twice.csv").string(), "second\n");
  }
} // namespace

TEST(OutputTransaction, RollBackLeavesTheDirectoryAsItWas)
{
  const fs::path dir = previous_run();
  {
    OutputTransaction t(dir.string());
    run_writes(dir);
    EXPECT_EQ(content(dir / "tables" / "old.csv"), "new\n");
  } // destroyed without commit: a failed run
  EXPECT_EQ(content(dir / "tables" / "old.csv"), "old\n");
  EXPECT_EQ(content(dir / "notes.txt"), "mine\n");
  EXPECT_FALSE(fs::exists(dir / "tables" / "twice.csv"));
  EXPECT_FALSE(fs::exists(dir / "system")); // the directories the run created are gone
  const auto entries = std::distance(fs::recursive_directory_iterator(dir), fs::recursive_directory_iterator());
  EXPECT_EQ(entries, 3); // tables/, tables/old.csv, notes.txt: no undo directory, no temporary
}

TEST(OutputTransaction, RollBackRemovesADirectoryItCreated)
{
  const fs::path dir = fs::path(test::temporary_directory()) / "fresh";
  fs::remove_all(dir);
  {
    OutputTransaction t(dir.string());
    prepare_output_directory((dir / "tables").string());
    run_writes(dir);
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(OutputTransaction, CommitKeepsTheNewFilesAndDropsTheUndo)
{
  const fs::path dir = previous_run();
  {
    OutputTransaction t(dir.string());
    run_writes(dir);
    t.commit();
  }
  EXPECT_EQ(content(dir / "tables" / "old.csv"), "new\n");
  EXPECT_EQ(content(dir / "tables" / "twice.csv"), "second\n");
  EXPECT_EQ(content(dir / "system" / "plots" / "a.dat"), "1\n");
  for (const auto &e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".servodrift-undo"), std::string::npos);
}

TEST(NonFiniteOutput, RefusedInResultFilesOnly)
{
  for (const std::string token : {"nan", "-nan", "NaN", "inf", "-Inf", "infinity", "nan(0x1)"})
    EXPECT_TRUE(is_non_finite_token(token)) << token;
  for (const std::string token : {"1e308", "", "info", "nanometre", "-"})
    EXPECT_FALSE(is_non_finite_token(token)) << token;

  const fs::path dir = fs::path(test::temporary_directory()) / "finite";
  fs::create_directories(dir);
  EXPECT_THROW(write_file_atomically((dir / "r.md").string(), "a | -nan % |\n"), std::runtime_error);
  EXPECT_THROW(write_file_atomically((dir / "r.json").string(), "{\"a\": inf}\n"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "r.md"));
  // prose and gnuplot's missing-value marker are fine
  EXPECT_NO_THROW(write_file_atomically((dir / "r.md").string(), "the information (infinite) nanometres\n"));
  EXPECT_NO_THROW(write_file_atomically((dir / "p.dat").string(), "1 NaN\n"));

  CsvDocument doc;
  doc.columns = {"a[1]", "b[1]"};
  doc.rows = {{"1", "2"}, {"3", format_cell(std::nan(""))}};
  try
    {
      (void)doc.text();
      FAIL() << "a NaN cell was accepted";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_NE(std::string(e.what()).find("column b[1], row 2"), std::string::npos) << e.what();
    }
}

// A CSV document reads back as it was written: comments (not the generated "# columns" line),
// columns and rows, empty cells kept; a column is found by its name with its unit.
TEST(CsvDocument, ParseReadsBackWhatTextWrote)
{
  CsvDocument doc;
  doc.comments = {"servodrift-output x", "a note, with a comma"};
  doc.columns = {"gap[m]", "estimate", "error[1]"};
  doc.rows = {{"1e-05", "three levels (order 2.1)", "-0.0118"}, {"4e-05", "two levels: order 2", ""}};
  const CsvDocument read = CsvDocument::parse(doc.text());
  EXPECT_EQ(read.comments, doc.comments);
  EXPECT_EQ(read.columns, doc.columns);
  ASSERT_EQ(read.rows.size(), 2u);
  EXPECT_EQ(read.rows[0], doc.rows[0]);
  EXPECT_EQ(read.rows[1][1], "two levels: order 2");
  EXPECT_EQ(read.column("error[1]"), 2u);
  EXPECT_THROW(read.column("error"), std::out_of_range);
}
