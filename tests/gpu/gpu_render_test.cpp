// The Vulkan backend against the CPU reference (the oracle) on every scene we have, against
// the course references, and on a scene that exceeds llvmpipe's loop budget. The validation
// layer is on for all of them (renderGpu checks that it stays silent).
#include <cmath>
#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

#include "image/encode.h"
#include "compare/image_diff.h"
#include "image/png.h"
#include "util/ray_counts.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// GPU (float32) against CPU (double): a silhouette or shadow-edge pixel may flip between hit
// and miss where the two round differently; allow 0.1% of pixels (at least 3) off by more
// than 2/255, and nothing else.
long long allowedFlips(const Image& img) { return std::max<long long>(3, img.width * img.height / 1000); }

class GpuFeatureScene : public ::testing::TestWithParam<std::string> {};
class GpuCourseScene : public ::testing::TestWithParam<const char*> {};

// The image with and without the exactness cut-off of the mirror loop, which must be the same;
// returns the mirror rays each traced.
std::pair<std::uint64_t, std::uint64_t> expectCutoffChangesNoPixel(const std::string& name, const SceneDesc& scene,
                                                                   std::uint32_t stepBudget = 0) {
  Context* context = gpuContextOrSkip();
  VulkanOptions exact;
  exact.cutoff = Cutoff::Off;
  VulkanOptions forced;
  forced.cutoff = Cutoff::On;   // also where Auto would leave it out
  forced.stepBudget = stepBudget;   // (a small budget suspends and resumes pixels)
  RayCounts cutRays, exactRays;   // (nonFinite checked by the renderGpu tests of the same scenes)
  GpuScene flat = flatten(scene);
  Image cut = encodeImage(renderVulkan(*context, flat, forced, &cutRays, nullptr), 1.0);
  Image all = encodeImage(renderVulkan(*context, flat, exact, &exactRays, nullptr), 1.0);
  EXPECT_TRUE(imagesClose("gpu-cutoff/" + name, cut, all, 0, 0));
  EXPECT_LE(cutRays.secondary, exactRays.secondary);
  EXPECT_EQ(context->validationMessages(), 0);
  return {cutRays.secondary, exactRays.secondary};
}

}  // namespace

TEST_P(GpuFeatureScene, MatchesCpuReference) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseSceneFile(sourcePath("scenes/" + GetParam() + ".test"));
  Image gpu = renderGpu(scene);
  Image cpu = renderScene(scene);
  EXPECT_TRUE(imagesClose("gpu-vs-cpu/" + GetParam(), gpu, cpu, 2, allowedFlips(cpu)));
}

// The two ways of reading the scene differ only in their loads: the images must be identical.
TEST_P(GpuFeatureScene, StorageAndTexelReadsAgreeExactly) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseSceneFile(sourcePath("scenes/" + GetParam() + ".test"));
  VulkanTimings storageRun, texelRun;
  Image storage = renderGpu(scene, 0, &storageRun, SceneReads::Storage);
  Image texel = renderGpu(scene, 0, &texelRun, SceneReads::Texel);
  EXPECT_FALSE(storageRun.texelReads);
  EXPECT_TRUE(texelRun.texelReads);
  EXPECT_TRUE(imagesClose("gpu-reads/" + GetParam(), texel, storage, 0, 0));
}

// Compiling out what a scene does not use must not change a pixel.
TEST_P(GpuFeatureScene, SpecializationChangesNoPixel) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseSceneFile(sourcePath("scenes/" + GetParam() + ".test"));
  VulkanOptions generic;
  generic.variant = ShaderVariant::General;
  VulkanTimings specializedRun, genericRun;
  Image specialized = renderGpu(scene, 0, &specializedRun);
  Image all = encodeImage(renderVulkan(*context, flatten(scene), generic, nullptr, &genericRun), 1.0);
  EXPECT_EQ(genericRun.leftOut, "");
  EXPECT_TRUE(imagesClose("gpu-specialize/" + GetParam(), specialized, all, 0, 0)) << "left out: " << specializedRun.leftOut;
}

// The general variant (every feature compiled in, the exactness cut-off told at run time
// whether to cut) renders the specialised variant's picture to the last bit, so that which
// one a render takes (ShaderVariant::Auto) changes nothing in any output format.
TEST_P(GpuFeatureScene, GeneralVariantIsTheSpecialisedBitForBit) {
  VKRT_REQUIRE_GPU(context);
  GpuScene flat = flatten(parseSceneFile(sourcePath("scenes/" + GetParam() + ".test")));
  VulkanOptions o;
  VulkanTimings specializedRun, generalRun;
  RadianceImage specialized = renderVulkan(*context, flat, o, nullptr, &specializedRun);
  o.variant = ShaderVariant::General;
  RadianceImage general = renderVulkan(*context, flat, o, nullptr, &generalRun);
  EXPECT_FALSE(specializedRun.general);
  EXPECT_TRUE(generalRun.general);
  EXPECT_TRUE(sameBits(specialized, general)) << "left out: " << specializedRun.leftOut;
}

TEST_P(GpuFeatureScene, CutoffChangesNoPixel) {
  VKRT_REQUIRE_GPU(context);
  expectCutoffChangesNoPixel(GetParam(), parseSceneFile(sourcePath("scenes/" + GetParam() + ".test")));
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuFeatureScene, ::testing::ValuesIn(projectSceneNames()),
                         [](const auto& p) { return p.param; });

// Issue tolerance: at most 30 pixels per scene off by more than 2/255 from the course's
// reference; and against the CPU reference, the same flip allowance as above.
TEST_P(GpuCourseScene, MatchesReferenceAndCpu) {
  auto dir = cse167Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse167Data);
  VKRT_REQUIRE_GPU(context);
  std::string name = GetParam();
  SceneDesc scene = parseScene(readFile(*dir + "/scenes/" + name + ".test"), name + ".test");
  Image gpu = renderGpu(scene);
  Image expected = readImage(*dir + "/verified-matches/" + name + ".png");
  EXPECT_TRUE(imagesClose("course-gpu/" + name, gpu, expected, 2, 30));
  ImageDiff d = compare(gpu, expected);
  std::printf("[ stats    ] %s (vulkan): %zu pixels differ at all, %lld by more than 2/255, max %d/255\n",
              name.c_str(), d.differing.size(), d.countOver(2), d.maxChannelDiff);
  Image cpu = renderScene(scene);
  EXPECT_TRUE(imagesClose("course-gpu-vs-cpu/" + name, gpu, cpu, 2, allowedFlips(cpu)));
}

TEST_P(GpuCourseScene, CutoffChangesNoPixel) {
  auto dir = cse167Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse167Data);
  VKRT_REQUIRE_GPU(context);
  std::string name = GetParam();
  auto [cut, all] = expectCutoffChangesNoPixel(name, parseScene(readFile(*dir + "/scenes/" + name + ".test"), name));
  std::printf("[ stats    ] %s: %llu of %llu mirror rays traced with the cut-off\n", name.c_str(),
              static_cast<unsigned long long>(cut), static_cast<unsigned long long>(all));
}

INSTANTIATE_TEST_SUITE_P(Cse167, GpuCourseScene,
                         ::testing::Values("scene4-ambient", "scene4-diffuse", "scene4-emission", "scene4-specular",
                                           "scene5", "scene6", "scene7"),
                         [](const auto& p) { return testName(p.param); });

// A pixel whose work exceeds llvmpipe's 65,535 loop iterations: 300 point lights, each a
// shadow ray through a BVH of 2000 triangles, on a pair of facing mirrors with maxdepth 8.
// Rendered in one go it would come out wrong with no error; vkrt suspends and resumes it.
std::string loopBudgetScene() {
  std::string s = "size 32 24\ncamera 0 -1 0.5 0 1 0.5 0 0 1 60\nmaxdepth 8\n";
  for (int i = 0; i < 300; ++i) {
    double x = -2.5 + 5.0 * (i % 20) / 19.0, z = 0.2 + 3.0 * (i / 20) / 14.0;
    s += "point " + std::to_string(x) + " 0 " + std::to_string(z) + " 0.004 0.004 0.004\n";
  }
  s += "ambient 0.01 0.01 0.01\ndiffuse 0.3 0.3 0.3\nspecular 0.7 0.7 0.7\nshininess 30\n";
  s += "vertex -3 -2 -1\nvertex 3 -2 -1\nvertex 3 -2 4\nvertex -3 -2 4\ntri 0 1 2\ntri 0 2 3\n";
  s += "pushTransform\ntranslate 0 4 0\ntri 0 2 1\ntri 0 3 2\npopTransform\n";
  // A cloud of small triangles between the mirrors: many BVH nodes on every shadow ray.
  int v = 4;
  for (int i = 0; i < 2000; ++i) {
    double x = -2.0 + 4.0 * ((i * 37) % 100) / 100.0, y = -1.5 + 3.0 * ((i * 53) % 97) / 97.0,
           z = -0.5 + 4.0 * ((i * 71) % 89) / 89.0;
    s += "vertex " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    s += "vertex " + std::to_string(x + 0.02) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    s += "vertex " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z + 0.02) + "\n";
    s += "tri " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + 2) + "\n";
    v += 3;
  }
  return s;
}

TEST(GpuLoopBudget, SceneBeyondTheBudgetMatchesCpu) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseScene(loopBudgetScene(), "loop-budget.test");
  VulkanTimings timings;
  Image gpu = renderGpu(scene, 0, &timings);
  EXPECT_GT(timings.suspensions, 0u) << "the scene no longer exceeds the step budget: make it harder";
  EXPECT_GT(timings.dispatches, timings.bands);
  Image cpu = renderScene(scene);
  EXPECT_TRUE(imagesClose("gpu-loop-budget", gpu, cpu, 2, allowedFlips(cpu)));
}

TEST(GpuLoopBudget, SuspendingAfterEveryFewStepsChangesNoPixel) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseSceneFile(sourcePath("scenes/deep_mirrors.test"));
  VulkanTimings tiny;
  Image whole = renderGpu(scene);
  Image pieces = renderGpu(scene, 5, &tiny);
  EXPECT_GT(tiny.suspensions, 1000u);
  EXPECT_TRUE(imagesClose("gpu-step-budget", pieces, whole, 0, 0));
}

// A deep tree, so that the budget also runs out in the middle of a descent through interior
// nodes (the inner loop of traversalStep), not only between leaves.
TEST(GpuLoopBudget, SuspendingInTheMiddleOfADescentChangesNoPixel) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseScene(loopBudgetScene(), "loop-budget.test");
  Image whole = renderGpu(scene);
  for (std::uint32_t budget : {3u, 7u}) {
    VulkanTimings tiny;
    Image pieces = renderGpu(scene, budget, &tiny);
    EXPECT_GT(tiny.suspensions, 10000u);
    EXPECT_TRUE(imagesClose("gpu-step-budget-descent-" + std::to_string(budget), pieces, whole, 0, 0));
  }
}

// The BVH walk's counts (RayCounts::boxTests and primitiveTests, which --stats prints a ray):
// the work of the walk, the same whatever the step budget (a suspended walk goes on where it
// stopped and tests nothing twice), the reads and the variant; a tree of one leaf tests its
// primitives once a ray and no box.
TEST(GpuWalkCounts, AreTheWalksWorkWhateverTheBudgetReadsAndVariant) {
  VKRT_REQUIRE_GPU(context);
  GpuScene deep = flatten(parseScene(loopBudgetScene(), "loop-budget.test"));
  auto counts = [&](const GpuScene& scene, std::uint32_t budget, SceneReads reads, ShaderVariant variant) {
    VulkanOptions o;
    o.testAll = false;   // (a small scene would test every primitive instead of walking)
    o.stepBudget = budget;
    o.reads = reads;
    o.variant = variant;
    RayCounts rays;
    renderVulkan(*context, scene, o, &rays, nullptr);
    return rays;
  };
  const RayCounts whole = counts(deep, 0, SceneReads::Auto, ShaderVariant::Specialized);
  EXPECT_GT(whole.boxTests, 2 * whole.total());   // several nodes a ray in a deep tree
  EXPECT_GT(whole.primitiveTests, 0u);
  for (std::uint32_t budget : {3u, 7u}) {
    const RayCounts tiny = counts(deep, budget, SceneReads::Auto, ShaderVariant::Specialized);
    EXPECT_EQ(tiny.boxTests, whole.boxTests) << "budget " << budget;
    EXPECT_EQ(tiny.primitiveTests, whole.primitiveTests) << "budget " << budget;
  }
  const RayCounts storage = counts(deep, 0, SceneReads::Storage, ShaderVariant::General);
  EXPECT_EQ(storage.boxTests, whole.boxTests);
  EXPECT_EQ(storage.primitiveTests, whole.primitiveTests);

  // One triangle: the root is a leaf, entered without a box test by every ray (camera and shadow).
  GpuScene one = flatten(parseScene("size 24 16\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 0 0 4 1 1 1\n"
                                    "vertex -1 -1 0\nvertex 1 -1 0\nvertex 0 1 0\ntri 0 1 2\n",
                                    "one.test"));
  const RayCounts leaf = counts(one, 0, SceneReads::Auto, ShaderVariant::Specialized);
  EXPECT_EQ(leaf.boxTests, 0u);
  EXPECT_EQ(leaf.primitiveTests, leaf.total());
  EXPECT_GT(leaf.shadow, 0u);
  EXPECT_EQ(context->validationMessages(), 0);
}

// Small scenes (testsEveryPrimitive), each primitive in the BVH, test every primitive with
// each ray instead of walking the BVH (kSpecTestAll, traverse.glsl's traceRay): the same bits
// as the walk, specialised and general, and suspended after every few steps, where a ray
// waits whole for the next dispatch.
TEST(GpuLoopBudget, TestingEveryPrimitiveChangesNoBit) {
  Context* context = gpuContextOrSkip();
  if (!context) return;
  for (const char* name : {"deep_mirrors", "shadows", "spheres", "trinormal", "attenuation", "transformed_triangles"}) {
    SCOPED_TRACE(name);
    GpuScene flat = flatten(parseSceneFile(sourcePath(std::string("scenes/") + name + ".test")));
    VulkanOptions walk;
    walk.testAll = false;
    VulkanTimings walked;
    RadianceImage expected = renderVulkan(*context, flat, walk, nullptr, &walked);
    EXPECT_FALSE(walked.testedAll);
    for (std::uint32_t budget : {0u, 2u, 5u}) {
      for (ShaderVariant variant : {ShaderVariant::Specialized, ShaderVariant::General}) {
        VulkanOptions all;
        all.stepBudget = budget;
        all.variant = variant;
        // Several pixels an invocation, as on a CPU device: a GPU's one pixel (a few steps in
        // these scenes) would not run out of even 5 steps, and nothing would be suspended.
        all.pixelsPerInvocation = gpu::kDefaultPixelsPerInvocation;
        VulkanTimings tested;
        RadianceImage image = renderVulkan(*context, flat, all, nullptr, &tested);
        EXPECT_TRUE(tested.testedAll);
        EXPECT_EQ(tested.general, variant == ShaderVariant::General);
        EXPECT_TRUE(sameBits(image, expected)) << "budget " << budget << ", general " << tested.general;
        if (budget > 0u) {
          EXPECT_GT(tested.suspensions, 100u) << "budget " << budget;
        }
      }
    }
  }
  EXPECT_EQ(context->validationMessages(), 0);
}

// The Whitted shader's invocations share out a band's pixels, each taking its next pixel when
// its pixel is done (raytrace.comp). However many pixels an invocation takes, however small
// the step budget (so that an invocation suspends in the middle of a pixel, then resumes and
// goes on to its next ones), and however many bands (the last one partial), every pixel is
// the one-pixel-per-invocation render's.
TEST(GpuLoopBudget, InvocationsTakingSeveralPixelsChangeNoPixel) {
  Context* context = gpuContextOrSkip();
  if (!context) return;
  const SceneDesc scenes[] = {parseSceneFile(sourcePath("scenes/deep_mirrors.test")),
                              parseScene(loopBudgetScene(), "loop-budget.test")};
  // The whole image, and a crop whose size is no multiple of the 8x8 tiles (partial tiles at
  // the right and at the bottom of the last band).
  const std::optional<PixelRect> crops[] = {std::nullopt, PixelRect{3, 2, 30, 21}};
  for (const SceneDesc& scene : scenes) {
    GpuScene flat = flatten(scene);
    for (const std::optional<PixelRect>& crop : crops) {
      VulkanOptions single;
      single.pixelsPerInvocation = 1;
      single.crop = crop;
      RayCounts expectedRays;
      const Image expected = encodeImage(renderVulkan(*context, flat, single, &expectedRays, nullptr), 1.0);
      for (std::uint32_t perInvocation : {5u, 64u, 100000u}) {
        for (std::uint32_t budget : {0u, 3u}) {
          for (std::size_t stateBytes : {std::size_t{64} << 20, sizeof(gpu::GpuWhittedState) * 64}) {
            VulkanOptions options;
            options.pixelsPerInvocation = perInvocation;
            options.stepBudget = budget;
            options.maxStateBytes = stateBytes;   // the small one: bands of 8 rows
            options.crop = crop;
            RayCounts rays;
            VulkanTimings timings;
            Image image = encodeImage(renderVulkan(*context, flat, options, &rays, &timings), 1.0);
            const std::string name = "gpu-pixels-per-invocation/" + std::string(crop ? "crop-" : "") +
                                     std::to_string(perInvocation) + "-" + std::to_string(budget) + "-" +
                                     std::to_string(stateBytes);
            EXPECT_TRUE(imagesClose(name, image, expected, 0, 0)) << name;
            EXPECT_EQ(rays.shadow, expectedRays.shadow) << name;   // each pixel traced once
            EXPECT_EQ(rays.secondary, expectedRays.secondary) << name;
            EXPECT_EQ(rays.nonFinite, 0u) << name;
            if (budget == 3u) {
              EXPECT_GT(timings.suspensions, 0u) << name;
            }
            if (stateBytes < (std::size_t{1} << 20) && perInvocation <= 5u) {
              EXPECT_GT(timings.bands, 1u) << name;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(context->validationMessages(), 0);
}

TEST(GpuCli, DefaultBackendIsVulkanAndStatsShowItsStages) {
  VKRT_REQUIRE_GPU(context);
  std::string dir = freshDir("gpu-cli/stats");
  // --variant specialized: the "left out" line is the specialised variant's (by default the
  // variant depends on whether this machine compiled it before: shader_variant_test.cpp).
  RunResult r = runVkrt("--stats --validation --variant specialized -o " + dir + "/o.png " + sourcePath("scenes/spheres.test"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* key : {"backend vulkan (", "instance", "device", "upload", "pipeline", "first dispatch (with JIT)",
                          "left out: triangles, smooth normals, point lights, attenuation", "dispatch", "readback",
                          "rays"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
  EXPECT_EQ(r.output.find("validation:"), std::string::npos) << r.output;
  Image gpu = readImage(dir + "/o.png");
  Image cpu = renderScene(parseSceneFile(sourcePath("scenes/spheres.test")));
  EXPECT_TRUE(imagesClose("gpu-cli", gpu, cpu, 2, allowedFlips(cpu)));
}

TEST(GpuCli, DeviceChoiceAndDeviceErrors) {
  VKRT_REQUIRE_GPU(context);
  std::string dir = freshDir("gpu-cli/devices");
  RunResult list = runVkrt("--list-devices");
  EXPECT_EQ(list.exitCode, 0) << list.output;
  EXPECT_NE(list.output.find("0: "), std::string::npos) << list.output;
  RunResult byIndex = runVkrt("-q --device 0 -o " + dir + "/a.png " + sourcePath("scenes/spheres.test"));
  EXPECT_EQ(byIndex.exitCode, 0) << byIndex.output;
  RunResult missing = runVkrt("--device 99 -o " + dir + "/b.png " + sourcePath("scenes/spheres.test"));
  EXPECT_EQ(missing.exitCode, 3) << missing.output;
  EXPECT_NE(missing.output.find("no Vulkan device 99; the devices are:"), std::string::npos) << missing.output;
  RunResult noName = runVkrt("--device no-such-gpu -o " + dir + "/b.png " + sourcePath("scenes/spheres.test"));
  EXPECT_EQ(noName.exitCode, 3) << noName.output;
  // No driver at all: exit 3, and the message says what to install. No file written.
  RunResult noDriver = runVkrt("-o " + dir + "/c.png " + sourcePath("scenes/spheres.test"),
                               "VK_DRIVER_FILES=/nonexistent/icd.json VK_ICD_FILENAMES=/nonexistent/icd.json");
  EXPECT_EQ(noDriver.exitCode, 3) << noDriver.output;
  EXPECT_NE(noDriver.output.find("mesa-vulkan-drivers"), std::string::npos) << noDriver.output;
  EXPECT_FALSE(fileExists(dir + "/b.png"));
  EXPECT_FALSE(fileExists(dir + "/c.png"));
  // The CPU backend needs no device.
  RunResult cpu = runVkrt("-q --backend cpu -o " + dir + "/d.png " + sourcePath("scenes/spheres.test"),
                          "VK_DRIVER_FILES=/nonexistent/icd.json VK_ICD_FILENAMES=/nonexistent/icd.json");
  EXPECT_EQ(cpu.exitCode, 0) << cpu.output;
}

// The largest maxdepth the parser accepts works on the Vulkan backend too: the million
// reflections of KnownAnswer.AMillionReflectionsBetweenParallelMirrors give the closed form's
// bytes (float32 is off by about 1e-4 here, each channel at least 0.3 of a step from a byte
// boundary) and the CPU reference's, exactly.
TEST(GpuEdgeCases, AMillionReflectionsMatchTheClosedFormAndTheCpu) {
  VKRT_REQUIRE_GPU(context);
  constexpr int kDepth = 1'000'000;
  SceneDesc scene = parseScene(parallelMirrorsScene(kDepth), "mirrors.test");
  ASSERT_EQ(scene.maxDepth, kDepth);
  VulkanTimings timings;
  Image gpu = renderGpu(scene, 0, &timings);
  ASSERT_EQ(gpu.width, 1);
  std::printf("[ stats    ] a million reflections on vulkan: %u dispatches, %llu suspensions\n",
              timings.dispatches, static_cast<unsigned long long>(timings.suspensions));
  for (int c = 0; c < 3; ++c) {
    double steps = 255.0 * parallelMirrorsRadiance(kParallelMirrorChannels[c], kDepth);
    EXPECT_EQ(static_cast<int>(gpu.pixel(0, 0)[c]), static_cast<int>(steps))
        << "channel " << c << ": 255 x radiance = " << steps;
  }
  EXPECT_TRUE(imagesClose("gpu-million-reflections", gpu, renderScene(scene), 0, 0));
}

TEST(GpuEdgeCases, EmptySceneAndLightsOnlyAreBlack) {
  VKRT_REQUIRE_GPU(context);
  for (const char* text : {"size 16 8\ncamera 0 0 5 0 0 0 0 1 0 45\n",
                           "size 16 8\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 0 0 2 1 1 1\ndirectional 0 0 1 1 1 1\n"}) {
    Image img = renderGpu(parseScene(text, "empty.test"));
    ASSERT_EQ(img.width, 16);
    for (std::uint8_t b : img.rgb) ASSERT_EQ(b, 0);
  }
}

// Between two wide, dim, parallel mirrors with maxdepth 40 nearly every path bounces 40
// times, but after a few bounces nothing can change a byte, and the cut-off must stop those
// paths. With a negative colour the bound is two-sided.
TEST(GpuCutoff, StopsPathsThatCannotChangeAByte) {
  VKRT_REQUIRE_GPU(context);
  auto scene = [](const std::string& diffuse) {
    return "size 40 30\ncamera 0 0 0 0 1 0.3 0 0 1 60\nmaxdepth 40\npoint 0 3 0 1 1 1\n"
           "ambient 0.05 0.05 0.05\ndiffuse " + diffuse + "\nspecular 0.1 0.1 0.1\nshininess 20\n"
           "vertex -1000 -1000 -1\nvertex 1000 -1000 -1\nvertex 1000 1000 -1\nvertex -1000 1000 -1\n"
           "tri 0 1 2\ntri 0 2 3\npushTransform\ntranslate 0 0 2\ntri 0 2 1\ntri 0 3 2\npopTransform\n"
           "sphere 0 4 0 0.5\n";
  };
  SceneDesc dim = parseScene(scene("0.4 0.5 0.6"), "dim.test");
  VulkanTimings automatic;
  renderVulkan(*context, flatten(dim), VulkanOptions{}, nullptr, &automatic);
  EXPECT_EQ(automatic.leftOut.find("exactness cut-off"), std::string::npos)
      << "--cutoff auto should use the cut-off here: " << automatic.leftOut;
  auto [cut, all] = expectCutoffChangesNoPixel("dim-mirrors", dim);
  EXPECT_LT(cut * 4, all) << "the cut-off no longer stops hopeless paths";
  std::printf("[ stats    ] dim mirrors: %llu of %llu mirror rays traced with the cut-off\n",
              static_cast<unsigned long long>(cut), static_cast<unsigned long long>(all));
  auto [cutNeg, allNeg] = expectCutoffChangesNoPixel("negative", parseScene(scene("0.4 -0.5 0.6"), "neg.test"));
  EXPECT_LT(cutNeg * 2, allNeg);
}

// Point lights without a constant attenuation term have no bound, and lights of one colour
// have a zero channel: a bound computed as 0 * infinity = NaN, which max()
// drops, would make the cut-off take every unbounded light for nothing and cut mirror paths that
// matter (thousands of pixels, up to 231/255). 200 such lights, mirror spheres on a floor,
// maxdepth 8; the same with a budget of 7 steps, which suspends nearly every pixel.
TEST(GpuCutoff, UnboundedLightsWithZeroChannelsChangeNoPixel) {
  VKRT_REQUIRE_GPU(context);
  std::string text = "size 64 48\nmaxdepth 8\ncamera 0 -6 4 0 0 0 0 0 1 45\nambient 0 0 0\nattenuation 0 0 1\n";
  const char* colours[] = {"0.1 0 0", "0 0.1 0", "0 0 0.1", "0.05 0.05 0"};
  for (int i = 0; i < 200; ++i)   // a fixed spread of positions above the floor
    text += "point " + std::to_string(-5 + (i * 37 % 100) / 10.0) + " " + std::to_string(-5 + (i * 61 % 100) / 10.0) +
            " " + std::to_string(1 + (i * 17 % 50) / 10.0) + " " + colours[i % 4] + "\n";
  text += "diffuse .5 .5 .5\nvertex -10 -10 0\nvertex 10 -10 0\nvertex 10 10 0\nvertex -10 10 0\ntri 0 1 2\ntri 0 2 3\n"
          "diffuse .1 .1 .1\nspecular .8 .8 .8\nshininess 50\nsphere -1.5 0 1 1\nsphere 1.5 0 1 1\nsphere 0 2 1 1\n";
  SceneDesc scene = parseScene(text, "unbounded-lights.test");
  GpuScene flat = flatten(scene);
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isinf(flat.cutoff.bound[c])) << "channel " << c;
  VulkanTimings automatic;
  renderVulkan(*context, flat, VulkanOptions{}, nullptr, &automatic);
  EXPECT_NE(automatic.leftOut.find("exactness cut-off"), std::string::npos)
      << "--cutoff auto cannot pay without a bound";
  for (std::uint32_t budget : {0u, 7u}) expectCutoffChangesNoPixel("unbounded-lights-" + std::to_string(budget), scene, budget);
}
