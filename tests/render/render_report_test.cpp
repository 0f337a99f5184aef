// What a render reports of itself (render/render.h, RenderReport): over a render of many
// sample batches, the Vulkan breakdown and the ray counts are the whole render's, not the
// last batch's.
#include <gtest/gtest.h>

#include "render/render.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

TEST(RenderReport, ATimedPathRenderReportsEveryBatch) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("render-report/batches");
  writeFile(dir + "/s.test",
            "size 16 12\ncamera 0 -3 1 0 0 0.5 0 0 1 45\nintegrator pathtracer\nspp 1\nnexteventestimation on\n"
            "quadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\nvertex -3 -3 0\nvertex 3 -3 0\n"
            "vertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\n");
  RenderRequest request;
  request.scenePath = dir + "/s.test";
  request.timeLimitSeconds = 2.0;   // batches of growing size until the time is up (the first holds any compile)
  ProgressBar progress(false);
  RenderReport report;
  RadianceImage image = renderSceneInMemory(request, progress, report, false);
  ASSERT_GE(report.batches, 2u) << "a two-second render of a 16x12 image takes several batches";
  EXPECT_EQ(image.samples, report.samples);
  EXPECT_EQ(report.rays.primary, report.samples * 16 * 12);   // every batch's camera rays
  EXPECT_GE(report.vulkan.dispatches, report.batches);        // at least one dispatch a batch
  EXPECT_GE(report.vulkan.bands, report.batches);
  EXPECT_GT(report.vulkan.firstDispatchSeconds, 0.0);
  EXPECT_GT(report.vulkan.dispatchSeconds, 0.0);   // the later batches' dispatches
}
