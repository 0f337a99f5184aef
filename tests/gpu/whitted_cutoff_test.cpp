// The exactness cut-off of the Whitted shader's mirror loop (raytrace.comp,
// restCannotChangePixel) on a pixel where one channel saturates and the others do not: a
// path may stop early only when every channel is saturated, since a mirror can still add to
// the channels that are not.
#include <gtest/gtest.h>

#include "gpu/vulkan_renderer.h"
#include "image/encode.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// A mirror facing the camera, lit from the side by a red point light bright enough to
// saturate red at the first hit (0.3 * 10 * 0.6 = 1.8 at the centre; no highlight there at
// shininess 1000), and reflecting an emitting cyan quad behind the camera, which adds
// 0.5 * 0.8 = 0.4 to green and blue on top of the direct 0.3 * 0.5 * 0.6 = 0.09.
constexpr const char* kScene =
    "size 24 16\ncamera 0 0 5 0 0 0 0 1 0 40\nmaxdepth 3\nambient 0 0 0\n"
    "point 4 0 3 10 0.5 0.5\n"
    "diffuse 0.3 0.3 0.3\nspecular 0.5 0.5 0.5\nshininess 1000\n"
    "vertex -20 -20 0\nvertex 20 -20 0\nvertex 20 20 0\nvertex -20 20 0\ntri 0 1 2\ntri 0 2 3\n"
    "diffuse 0 0 0\nspecular 0 0 0\nemission 0 0.8 0.8\n"
    "vertex -40 -40 8\nvertex 40 -40 8\nvertex 40 40 8\nvertex -40 40 8\ntri 4 6 5\ntri 4 7 6\n";

TEST(WhittedCutoff, OneSaturatedChannelDoesNotStopThePath) {
  Context* context = gpuContextOrSkip();
  if (!context) return;
  const SceneDesc scene = parseScene(kScene, "saturated-red.test");
  const GpuScene flat = flatten(scene);
  VulkanOptions on, off;
  on.cutoff = Cutoff::On;
  off.cutoff = Cutoff::Off;
  const Image cut = encodeImage(renderVulkan(*context, flat, on, nullptr, nullptr), 1.0);
  const Image exact = encodeImage(renderVulkan(*context, flat, off, nullptr, nullptr), 1.0);
  const Image cpu = renderScene(scene);
  EXPECT_EQ(context->validationMessages(), 0);
  // The centre pixel: red saturated, green the direct 0.09 plus the mirror's 0.4.
  const std::size_t centre = (static_cast<std::size_t>(cpu.height / 2) * cpu.width + cpu.width / 2) * 3;
  EXPECT_EQ(cpu.rgb[centre], 255);
  EXPECT_NEAR(cpu.rgb[centre + 1], 0.49 * 255, 2.0);
  EXPECT_TRUE(imagesClose("whitted-cutoff/saturated-red-on-vs-off", cut, exact, 0, 0));
  EXPECT_TRUE(imagesClose("whitted-cutoff/saturated-red-on-vs-cpu", cut, cpu, 1, 0));
}

}  // namespace
