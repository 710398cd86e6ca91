// The test executables' main: GoogleTest's, after the allocator tuning the lacrima command has,
// so that tests which build frames measure and run as the command does.
#include <gtest/gtest.h>

#include "lacrima/base/allocator_tuning.hpp"

int main(int argc, char** argv) {
  lacrima::keepFreedMemoryForReuse();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
