// GoogleTest main that initialises MPI (through deal.II) as servodrift's main does, so that the
// sweep runner works the same in the tests. The temporary output directories of a passing run are
// removed; a failing run keeps them (the failure messages name them).
#include "common/sweep.h"
#include "tests/support/test_support.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace
{
  /// Open MPI 4.1 singletons that start or end at the same moment race for the session directory
  /// they share under /tmp (open-mpi/ompi#8510: "A call to mkdir was unable to create the desired
  /// directory ... File exists"; `ctest -j2' hit it once). A test process that mpirun did not start
  /// gets a session directory of its own (tests/CMakeLists.txt does the same for the command-line
  /// tests), removed when it ends, after MPI_Finalize.
  struct PrivateMpiSessionDirectory
  {
    std::filesystem::path path;
    PrivateMpiSessionDirectory()
    {
      if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
        return;
      path = std::filesystem::temp_directory_path() / ("servodrift-test-mpi-" + std::to_string(::getpid()));
      ::setenv("OMPI_MCA_orte_tmpdir_base", path.c_str(), 1);
    }
    ~PrivateMpiSessionDirectory()
    {
      std::error_code ignored;
      if (!path.empty())
        std::filesystem::remove_all(path, ignored);
    }
  };
} // namespace

namespace
{
  /// ctest's test discovery runs `--gtest_list_tests' with a time limit when the suite starts; it
  /// needs no MPI, whose start-up alone (a few seconds on a loaded machine) once ran past the limit.
  bool only_lists_tests(int argc, char **argv)
  {
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--gtest_list_tests")
        return true;
    return false;
  }
} // namespace

int main(int argc, char **argv)
{
  if (only_lists_tests(argc, argv))
  {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
  }
  const PrivateMpiSessionDirectory session; // before MPI_Init, removed after MPI_Finalize
  servodrift::one_thread_per_process();
  servodrift::prepare_mpi_singleton();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  if (result == 0)
    servodrift::test::remove_temporary_directories();
  return result;
}
