// The pace of the Vulkan renderers' dispatches (host/gpu/band_dispatch.h): the step budget
// follows the time a dispatch took, so that a stop request is seen a few times a second on a
// slow device and a fast one keeps its long dispatches.
#include <gtest/gtest.h>

#include "gpu/band_dispatch.h"
#include "gpu_types.h"

namespace vkrt {
namespace {

constexpr std::uint32_t kMax = gpu::kDefaultStepBudget;

TEST(DispatchPace, ASlowDispatchShrinksTheBudgetInProportion) {
  // Ten times the target: a tenth of the steps.
  EXPECT_EQ(pacedStepBudget(8000, 10 * kTargetDispatchSeconds, kMax), 800u);
  EXPECT_EQ(pacedStepBudget(1000, 100 * kTargetDispatchSeconds, kMax), kMinStepBudget);
  EXPECT_EQ(pacedStepBudget(8000, 4 * kTargetDispatchSeconds, kMax), 2000u);
}

TEST(DispatchPace, NeverBelowTheFloorNorAboveTheCeiling) {
  EXPECT_EQ(pacedStepBudget(100, 1000 * kTargetDispatchSeconds, kMax), kMinStepBudget);
  EXPECT_EQ(pacedStepBudget(kMinStepBudget, 1000.0, kMax), kMinStepBudget);
  EXPECT_EQ(pacedStepBudget(kMax, kTargetDispatchSeconds / 100, kMax), kMax);
  // A ceiling under the floor (a test's tiny budget) is kept as it is.
  EXPECT_EQ(pacedStepBudget(5, 100.0, 5), 5u);
  EXPECT_EQ(pacedStepBudget(5, 0.0, 5), 5u);
}

TEST(DispatchPace, ACpuDeviceStartsWithAboutTheFirstDispatchsSteps) {
  EXPECT_EQ(firstStepBudget(kMax, 160000, true, 16e6), 100u);
  EXPECT_EQ(firstStepBudget(kMax, 100, true, 16e6), kMax);                    // a small image: the whole budget
  EXPECT_EQ(firstStepBudget(kMax, 100000000, true, 16e6), kMinStepBudget);   // never below the floor
  EXPECT_EQ(firstStepBudget(kMax, 160000, false, 16e6), kMax);                // a GPU: the whole budget
  // A 640x480 Whitted image (16 pixels an invocation) starts at the whole budget on lavapipe.
  EXPECT_EQ(firstStepBudget(kMax, 640 * 480 / 16, true, kWhittedFirstDispatchSteps), kMax);
}

TEST(DispatchPace, AShortDispatchGrowsTheBudgetAtMostFourTimes) {
  EXPECT_EQ(pacedStepBudget(1000, kTargetDispatchSeconds / 100, kMax), 4000u);
  EXPECT_EQ(pacedStepBudget(1000, 0.0, kMax), 4000u);   // a clock too coarse to see it
  EXPECT_EQ(pacedStepBudget(1000, kTargetDispatchSeconds / 1.5, kMax), 1500u);
}

}  // namespace
}  // namespace vkrt
