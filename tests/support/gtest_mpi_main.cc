// GoogleTest main that initialises MPI (through deal.II) as servodrift's main does, so that the
// sweep runner works the same in the tests. The temporary output directories of a passing run are
// removed; a failing run keeps them (the failure messages name them).
#include "tests/support/test_support.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  if (result == 0)
    servodrift::test::remove_temporary_directories();
  return result;
}
