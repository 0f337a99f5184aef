// Differential testing (tests/differential.h): random scenes from fixed seeds, and the scenes
// of tests/differential/regressions/ (disagreements found before), each through four checks.
// vkrt_difftest runs thousands of seeds by hand.
//
// Tolerances, stated once in differential.h and applied here through imagesClose():
//  a. Vulkan against the CPU reference, c. the scene x1e-3, x1e4 and moved by 1e4 against
//     itself, d. the scene with a vast black ground against itself: at most 0.1% of the
//     pixels, and at least 3, may differ by more than 2/255 (a silhouette or shadow-edge pixel
//     may flip where two renders round differently; the tolerance of the other GPU tests);
//  b. the exactness cut-off on against off, with the default step budget and with 3 or 7
//     steps per dispatch (pixels suspended and resumed), and suspension alone: bit for bit.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "differential.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "scene/shapes/sphere.h"
#include "scene_generator.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::difftest;
using namespace vkrt::test;

namespace {

// The seeds run by the suite: 1 to kSuiteSeeds, every kind of scene among them (22 mixed,
// 12 mirror halls, 6 vast floors). Measured on this 2-core machine under ctest -j2, with the
// regression scenes: about 40 s with a fresh Mesa shader cache, 70 s with none.
constexpr std::uint64_t kSuiteSeeds = 40;

struct Case {
  std::string name;   // test-name safe: seed_17, or the regression file's stem
  std::string text;
  std::uint32_t stepBudget = 3;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  std::vector<Case> all;
  for (std::uint64_t seed = 1; seed <= kSuiteSeeds; ++seed)
    all.push_back({"seed_" + std::to_string(seed), generateScene(seed), stepBudgetForSeed(seed)});
  return all;
}

std::vector<Case> regressionCases() {
  std::vector<Case> all;
  namespace fs = std::filesystem;
  fs::path dir = sourcePath("tests/differential/regressions");
  if (!fs::is_directory(dir)) return all;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".test") continue;
    std::string text = readFile(entry.path().string());
    std::string name = entry.path().stem().string();
    for (char& ch : name)
      if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    all.push_back({name, text, stepBudgetOfText(text)});
  }
  std::sort(all.begin(), all.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
  return all;
}

// Runs one check on one scene; every comparison and problem becomes a failure naming them.
// Without a Vulkan device, checks a and b are skipped (failed in CI) and c and d run their
// CPU halves only.
void expectCheck(Check check, const Case& c) {
  Context* context = gpuContextOrSkip();
  if (!context && (check == kBackends || check == kCutoff)) return;
  CheckOptions options;
  options.checks = check;
  options.stepBudget = c.stepBudget;
  options.context = context;
  Outcome outcome = runChecks(c.text, c.name, options);
  for (const auto& [which, what] : outcome.problems) ADD_FAILURE() << "check " << checkLetter(which) << ": " << what;
  for (const std::string& note : outcome.notes) std::printf("[ note     ] %s: %s\n", c.name.c_str(), note.c_str());
  for (const Comparison& cmp : outcome.comparisons) {
    std::string name = std::string("differential/") + c.name + "/" + cmp.name;
    ::testing::AssertionResult result =
        imagesClose(name, cmp.actual, cmp.expected, cmp.stepTolerance, cmp.allowedOver);
    if (result) continue;
    // Beside the images: the scene, and the rewritten one that disagreed with it.
    std::string dir = outputPath("failures/" + name);
    writeFile(dir + "/scene.test", c.text);
    if (!cmp.variantText.empty()) writeFile(dir + "/variant.test", cmp.variantText);
    ADD_FAILURE() << "check " << checkLetter(check) << " (" << checkName(check) << "), " << cmp.actualLabel
                  << " against " << cmp.expectedLabel << ": " << result.message() << "\n  scene:    " << dir
                  << "/scene.test" << (cmp.variantText.empty() ? "" : "\n  variant:  " + dir + "/variant.test");
  }
}

class DifferentialTest : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(DifferentialTest, VulkanMatchesCpu) { expectCheck(kBackends, GetParam()); }
TEST_P(DifferentialTest, CutoffAndSuspensionChangeNoPixel) { expectCheck(kCutoff, GetParam()); }
TEST_P(DifferentialTest, SamePictureScaledAndMoved) { expectCheck(kMetamorphic, GetParam()); }
TEST_P(DifferentialTest, VastBlackGroundChangesNoPixel) { expectCheck(kGround, GetParam()); }

INSTANTIATE_TEST_SUITE_P(Seeds, DifferentialTest, ::testing::ValuesIn(cases()),
                         [](const auto& p) { return p.param.name; });
INSTANTIATE_TEST_SUITE_P(Regressions, DifferentialTest, ::testing::ValuesIn(regressionCases()),
                         [](const auto& p) { return p.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(DifferentialTest);

// The generator is deterministic (its own splitmix64, no std distributions) and writes
// scenes that parse; its rewrites move the camera and rescale attenuation.
TEST(DifferentialGenerator, SeedsNameTheSameValidScenes) {
  Rng rng(0);
  EXPECT_EQ(rng.next(), 0xE220A8397B1DCDAFull);   // splitmix64's published first output for 0
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    std::string text = generateScene(seed);
    ASSERT_EQ(text, generateScene(seed));
    SCOPED_TRACE("seed " + std::to_string(seed) + "\n" + text);
    SceneDesc scene = parseScene(text, "generated.test");
    EXPECT_GE(scene.lights.size(), 1u);
    EXPECT_LE(scene.lights.size(), 250u);
    EXPECT_LE(scene.width * scene.height, 64 * 64);
    EXPECT_NO_THROW(parseScene(scaledAndMoved(text, 1e-3, dvec3(1e4)), "scaled.test"));
  }
}

TEST(DifferentialGenerator, ScaledAndMovedRewritesCameraAndAttenuation) {
  std::string text = "size 4 3\ncamera 1 2 3 0 0 0 0 1 0 45\nattenuation 1 2 4\npoint 1 1 1 1 1 1\nsphere 0 0 0 1\n";
  SceneDesc a = parseScene(text, "a.test");
  SceneDesc b = parseScene(scaledAndMoved(text, 10.0, dvec3(5, 0, 0)), "b.test");
  EXPECT_EQ(b.camera.from, dvec3(15, 20, 30));
  EXPECT_EQ(b.camera.at, dvec3(5, 0, 0));
  EXPECT_EQ(b.camera.up, a.camera.up);
  ASSERT_EQ(b.lights.size(), 1u);
  EXPECT_EQ(b.lights[0].vec, dvec3(15, 10, 10));
  EXPECT_DOUBLE_EQ(b.lights[0].attenuation.x, 1.0);
  EXPECT_DOUBLE_EQ(b.lights[0].attenuation.y, 0.2);
  EXPECT_DOUBLE_EQ(b.lights[0].attenuation.z, 0.04);
  ASSERT_EQ(b.spheres.size(), 1u);
  EXPECT_EQ(b.spheres[0].worldFromObject[3], glm::dvec4(5, 0, 0, 1));
}

TEST(DifferentialGenerator, VastGroundLiesBelowEverythingAndAwayFromTheLights) {
  std::string text = "size 4 3\ncamera 0 2 5 0 0 0 0 1 0 45\ndirectional 1 1 0 1 1 1\npoint 0 3 0 1 1 1\n"
                     "sphere 0 0 0 1\n";
  SceneDesc scene = parseScene(text, "a.test");
  auto grounded = withVastBlackGround(text, scene);
  ASSERT_TRUE(grounded.has_value());
  SceneDesc g = parseScene(*grounded, "g.test");
  ASSERT_EQ(g.spheres.size(), 2u);
  dvec3 lo, hi;
  shapes::bounds(g.spheres[0], lo, hi);
  EXPECT_LT(hi.y, -1.0);                // below the sphere (the lowest point)
  EXPECT_GT(hi.x - lo.x, 1000.0);       // vast
  EXPECT_EQ(g.materials[g.spheres[0].material], (Material{dvec3(0.0), dvec3(0.0), dvec3(0.0), dvec3(0.0), 0.0}));
  EXPECT_EQ(g.materials[g.spheres[1].material], scene.materials[scene.spheres[0].material]);
  // Lights on every side: no ground can be added.
  std::string surrounded = text + "directional 0 -1 0 1 1 1\ndirectional 1 0 0 1 1 1\ndirectional -1 0 0 1 1 1\n"
                                  "directional 0 0 1 1 1 1\ndirectional 0 0 -1 1 1 1\n";
  EXPECT_FALSE(withVastBlackGround(surrounded, parseScene(surrounded, "s.test")).has_value());
}
