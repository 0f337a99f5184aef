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

// The first batch's pipeline is made while the BVH builds, from the scene's arrays
// (prepareVulkanPipeline, prepareVulkanPathPipeline), and the batch takes that one: the
// render makes one pipeline in all, as it did when the batch made its own. That holds too
// where the BVH leaves a primitive out (one that can never be hit), which decides whether a
// small scene's rays test every primitive.
TEST(RenderReport, TheFirstBatchTakesThePipelineMadeWhileTheBvhBuilt) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("render-report/pipeline-ahead");
  const std::string geometry =
      "vertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\n"
      "sphere 0 0 0.5 0.5\n";
  writeFile(dir + "/whitted.test", "size 24 16\ncamera 0 -3 1 0 0 0.5 0 0 1 45\npoint 0 -2 3 1 1 1\n"
                                   "diffuse 0.7 0.5 0.3\nspecular 0.2 0.2 0.2\n" + geometry);
  const std::string path = "size 24 16\ncamera 0 -3 1 0 0 0.5 0 0 1 45\nintegrator pathtracer\nspp 3\n"
                           "nexteventestimation on\nquadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\n";
  writeFile(dir + "/path.test", path + geometry);
  // The same with a triangle of zero area, which the BVH leaves out: rays then walk the BVH
  // instead of testing every primitive.
  writeFile(dir + "/degenerate.test", path + geometry + "tri 0 1 1\n");
  writeFile(dir + "/whitted-degenerate.test", "size 24 16\ncamera 0 -3 1 0 0 0.5 0 0 1 45\npoint 0 -2 3 1 1 1\n"
                                              "diffuse 0.7 0.5 0.3\n" + geometry + "tri 0 1 1\n");
  for (const std::string name : {"whitted", "whitted-degenerate", "path", "degenerate"}) {
    SCOPED_TRACE(name);
    RenderRequest request;
    request.scenePath = dir + "/" + name + ".test";
    ProgressBar progress(false);
    RenderReport report;
    RadianceImage image = renderSceneInMemory(request, progress, report, false);
    EXPECT_EQ(image.width, 24);
    EXPECT_GT(report.pipelineAheadSeconds, 0.0);
    EXPECT_EQ(report.pipelinesMade, 1u);
    EXPECT_EQ(report.vulkan.testedAll, name.find("degenerate") == std::string::npos);
  }
}
