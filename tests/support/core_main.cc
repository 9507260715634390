// GoogleTest main of the tests that link only the lean core: no MPI; the temporary directories of a
// passing run are removed, a failing run keeps them.
#include "tests/support/core_support.h"

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  if (result == 0)
    servodrift::test::remove_temporary_directories();
  return result;
}
