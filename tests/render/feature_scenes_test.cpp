// The project's own scenes (scenes/*.test): each parses, renders, is deterministic across
// thread counts, and shows the feature it is named for.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "image/encode.h"
#include "cpu/reference.h"
#include "compare/image_diff.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

SceneDesc load(const std::string& name) { return parseSceneFile(sourcePath("scenes/" + name + ".test")); }

Image render(const SceneDesc& s, int threads) {
  Bvh bvh = buildBvh(s);
  CpuOptions o;
  o.threads = threads;
  return encodeImage(renderReference(s, bvh, o, nullptr), 1.0);
}

class FeatureScene : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST(FeatureScenes, AllPresent) {
  auto names = projectSceneNames();
  for (const char* n : {"showcase", "spheres", "transformed_triangles", "trinormal", "shadows", "attenuation",
                        "deep_mirrors", "non_square"})
    EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
}

TEST_P(FeatureScene, RendersTheSameOnOneThreadAndOnMany) {
  SceneDesc s = load(GetParam());
  Image one = render(s, 1), many = render(s, 4);
  EXPECT_TRUE(imagesClose("threads/" + GetParam(), many, one, 0, 0));
  long long lit = 0;
  for (std::uint8_t b : one.rgb) lit += b > 0;
  EXPECT_GT(lit, static_cast<long long>(one.rgb.size() / 20)) << "mostly black";
}

INSTANTIATE_TEST_SUITE_P(Scenes, FeatureScene, ::testing::ValuesIn(projectSceneNames()),
                         [](const auto& p) { return p.param; });

TEST(FeatureScenes, DeepMirrorsDependOnMaxDepth) {
  SceneDesc s = load("deep_mirrors");
  Image deep = render(s, 0);
  s.maxDepth = 1;
  Image shallow = render(s, 0);
  ImageDiff d = compare(deep, shallow);
  EXPECT_GT(d.differing.size(), 100u) << "the extra reflections changed nothing";
  s.maxDepth = 11;
  Image almost = render(s, 0);
  EXPECT_LT(compare(deep, almost).maxChannelDiff, 8) << "reflection 12 should be faint (0.9^12 throughput)";
}

// Two floor pixels inside the sphere's shadows, where the camera sees the floor (not the
// sphere) with and without the sphere, so the images differ there only by the shadow rays.
// The floor: ambient 0.1, diffuse 0.7, no specular, normal +z. In the point light's shadow
// (22, 21) only the directional light (0.3, N.L = cos 45 deg) is left:
// 0.1 + 0.7 * 0.3 * 0.7071 = 0.2485 -> 63. In the directional light's shadow (40, 24) the
// pixel loses that directional term, 37.87 steps, against the scene without the sphere.
TEST(FeatureScenes, ShadowsDarkenTheFloor) {
  SceneDesc s = load("shadows");
  Image with = render(s, 0);
  s.spheres.clear();
  Image without = render(s, 0);
  const double directionalSteps = 255.0 * 0.7 * 0.3 * std::sqrt(0.5);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(static_cast<int>(with.pixel(22, 21)[c]), 63) << "in the point light's shadow, channel " << c;
    EXPECT_GT(static_cast<int>(without.pixel(22, 21)[c]), 63 + 50)
        << "lit by the point light without the sphere, channel " << c;
    EXPECT_NEAR(without.pixel(40, 24)[c] - with.pixel(40, 24)[c], directionalSteps, 1.0)
        << "in the directional light's shadow, channel " << c;
  }
}

TEST(FeatureScenes, AttenuationIsPerLight) {
  // The right light has attenuation 0 0 1 (quadratic), the left none: at equal distance the
  // left one's red contribution beats the right one's blue relative to their colours.
  SceneDesc s = load("attenuation");
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].attenuation, dvec3(1, 0, 0));
  EXPECT_EQ(s.lights[1].attenuation, dvec3(0, 0, 1));
  Image img = render(s, 0);
  // Directly under each light the floor is at distance 1: both unattenuated there.
  const std::uint8_t* left = img.pixel(16, 24);
  const std::uint8_t* right = img.pixel(47, 24);
  EXPECT_GT(left[0], left[2]);
  EXPECT_GT(right[2], right[0]);
}
