// The pace of the Vulkan renderers' dispatches (host/gpu/band_dispatch.h): the step budget
// follows the time a dispatch took, so that a stop request is seen a few times a second on a
// slow device and a fast one keeps its long dispatches.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/band_dispatch.h"
#include "gpu/vulkan_path_renderer.h"
#include "gpu_types.h"

namespace vkrt {
namespace {

constexpr std::uint32_t kMax = gpu::kDefaultStepBudget;

TEST(DispatchPace, ASlowDispatchShrinksTheBudgetInProportion) {
  // Ten times the target: a tenth of the steps.
  EXPECT_NEAR(pacedStepBudget(8000, 10 * kTargetDispatchSeconds, kMax), 800u, 1);
  EXPECT_EQ(pacedStepBudget(1000, 100 * kTargetDispatchSeconds, kMax), kMinStepBudget);
  EXPECT_NEAR(pacedStepBudget(8000, 4 * kTargetDispatchSeconds, kMax), 2000u, 1);
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

// A band's first dispatch runs every pixel of it: it starts at the budget the band before
// started at (as paced by that dispatch), not at the one the few pixels of that band's last
// dispatches grew it to.
TEST(DispatchPace, EachBandStartsAtTheBudgetOfTheLastBandsStart) {
  std::uint32_t budget = 1000;
  StepPace pace{&budget, kMax};
  pace.before(true);
  EXPECT_EQ(budget, 1000u);                      // nothing learnt yet
  pace.after(true, 2 * kTargetDispatchSeconds);  // the band's first dispatch: twice too long
  EXPECT_EQ(budget, 500u);
  for (int i = 0; i < 3; ++i) pace.after(false, kTargetDispatchSeconds / 100);   // its few last pixels
  EXPECT_EQ(budget, 32000u > kMax ? kMax : 32000u);
  pace.before(true);
  EXPECT_EQ(budget, 500u);
}

// Bands sized by time: one dispatch of the next band runs its pixels for as many steps as a
// pixel of the last took, in about the target time.
TEST(BandRows, ADispatchOfTheNextBandTakesAboutTheTarget) {
  // 1e8 steps a second, 4000 steps a pixel, 400 pixels a row: 0.3 s is 18.75 rows, so 16.
  const double speed = 1e8 * kTargetDispatchSeconds / 0.3;
  EXPECT_EQ(timedBandRows(speed, 4000, kMax, 400, 168), 16u);
  // A pixel that took more steps than a dispatch runs: the budget's steps a dispatch.
  EXPECT_EQ(timedBandRows(speed, 1e6, 2000, 400, 168), timedBandRows(speed, 2000, 2000, 400, 168));
  // Short paths: as many rows as the memory takes; never fewer than a tile's.
  EXPECT_EQ(timedBandRows(speed, 10, kMax, 400, 168), 168u);
  EXPECT_EQ(timedBandRows(1.0, 4000, kMax, 400, 168), 8u);
  EXPECT_EQ(timedBandRows(0.0, 4000, kMax, 400, 168), 8u);    // nothing measured
  EXPECT_EQ(timedBandRows(std::nan(""), 4000, kMax, 400, 168), 8u);
}

TEST(BandRows, TheFirstBandOnACpuTakesAboutTheFirstDispatchsSteps) {
  // 20e6 steps at 8192 a pixel over 400 pixels a row: 6.1 rows, so one tile's.
  EXPECT_EQ(firstTimedBandRows(kMax, 400, 168, true, 20e6), 8u);
  EXPECT_EQ(firstTimedBandRows(kMax / 16, 400, 168, true, 20e6), 96u);   // 16 pixels a lane
  EXPECT_EQ(firstTimedBandRows(kMax, 400, 168, false, 20e6), 168u);      // a GPU: the memory's rows
}

// The path shader's lanes take several pixels only where path lengths differ (the
// pathtracer) on a CPU device, fewer in a large scene, and one each for many samples.
TEST(PathLanes, SeveralPixelsALaneOnlyWherePathsDifferInLength) {
  const std::uint32_t pt = gpu::kIntegratorPathTracer;
  EXPECT_EQ(pathPixelsPerInvocation(true, pt, 1, 30), gpu::kDefaultPixelsPerInvocation);
  EXPECT_EQ(pathPixelsPerInvocation(true, pt, 64, 30), kPathSamplesPerLane / 64);
  EXPECT_EQ(pathPixelsPerInvocation(true, pt, 1000, 30), 1u);
  EXPECT_EQ(pathPixelsPerInvocation(true, pt, 2, kLargeScenePrimitives + 1), 4u);
  EXPECT_EQ(pathPixelsPerInvocation(true, gpu::kIntegratorDirect, 2, 30), 1u);
  EXPECT_EQ(pathPixelsPerInvocation(true, gpu::kIntegratorAnalyticDirect, 2, 30), 1u);
  EXPECT_EQ(pathPixelsPerInvocation(false, pt, 1, 30), 1u);   // a GPU has lanes to spare
}

}  // namespace
}  // namespace vkrt
