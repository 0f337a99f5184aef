// The grazing term of the secondary-ray offset (gpu_limits.h;
// setSecondaryOffsets in intersect.glsl, secondaryRayOffsets in host/scene/ray_offset.cpp) on
// an image: a floor lit by a directional light 0.001 degrees above it, seen from about a
// hundred units away. The float32 hit point lies up to a few ulps of its magnitude below the
// floor, and a shadow ray leaving at cos = 2e-5 crosses back through the floor only after
// depth / cos, beyond the primitive's own offset (1e-2 for a floor 283 units across): without
// the term kGrazingPerMagnitude * magnitude / cos (here about 2.5 units) such pixels shadow
// themselves. The double-precision reference has no such error: both must show the floor lit.
#include <algorithm>

#include <gtest/gtest.h>

#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

constexpr const char* kScene =
    "size 32 32\ncamera 0 30 100 0 0 0 0 1 0 10\nambient 0 0 0\n"
    "directional 0 0.00002 1 20000 20000 20000\n"
    "diffuse 0.8 0.8 0.8\n"
    "vertex -100 0 -100\nvertex 100 0 -100\nvertex 100 0 100\nvertex -100 0 100\ntri 0 2 1\ntri 0 3 2\n";

TEST(GrazingOffset, GrazingShadowRaysDoNotShadowTheirOwnSurface) {
  const SceneDesc scene = parseScene(kScene, "grazing-light.test");
  // Lit: 0.8 * 20000 * 2e-5 = 0.32 of full scale everywhere (81/255).
  const Image cpu = renderScene(scene);
  EXPECT_EQ(*std::min_element(cpu.rgb.begin(), cpu.rgb.end()), 81);
  EXPECT_EQ(*std::max_element(cpu.rgb.begin(), cpu.rgb.end()), 81);
  VKRT_REQUIRE_GPU(context);
  const Image gpu = renderGpu(scene);
  EXPECT_TRUE(imagesClose("grazing-offset/floor", gpu, cpu, 1, 0));
}

}  // namespace
