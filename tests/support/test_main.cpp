// Test entry point: says where the course data comes from, or that it is absent.
#include <cstdio>

#include <gtest/gtest.h>

#include "test_support.h"

int main(int argc, char** argv) {
  // A copy of this binary that runs vkrt to measure its peak memory (runVkrtMeasuringMemory).
  if (int status = vkrt::test::measurePeakMemoryMain(argc, argv); status >= 0) return status;
  ::testing::InitGoogleTest(&argc, argv);
  auto dir = vkrt::test::cse167Dir();
  if (!dir)
    std::fprintf(stderr, "note: course data (../shared/cse167) not found: tests that need it %s\n",
                 vkrt::test::inCi() ? "FAIL (CI=true)" : "are skipped");
  int status = RUN_ALL_TESTS();
  vkrt::test::releaseGpuContext();
  return status;
}
