// The two backends follow the same paths: the CPU reference (double precision) and the shader
// (float32) draw the same random numbers by the rules of gpu_rng.h, so one seed gives nearly
// the same image on both, pixel by pixel, on every CSE 168 course scene. Where a float32 ray
// and its double twin part at an edge, the two paths go separate ways: a few pixels may differ.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/path_reference.h"
#include "gpu/vulkan_path_renderer.h"
#include "image/image.h"
#include "path_scenes.h"
#include "render/render.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// The image as the output encodes it (doc/path-tracing.md, "Commands", `gamma`).
Image encoded(const RadianceImage& r, double gamma) {
  Image img(r.width, r.height);
  for (std::size_t i = 0; i < r.rgb.size(); ++i) img.rgb[i] = radianceToByte(std::pow(std::max(0.0, double(r.rgb[i])), 1.0 / gamma));
  return img;
}

double mean(const RadianceImage& r) {
  double s = 0;
  for (float v : r.rgb) s += v;
  return s / static_cast<double>(r.rgb.size());
}

// A 32x32 crop below the image's centre, samples [0, 4) of the scene's render, seed 17.
// Tolerance: at most 3% of the pixels (30 of 1024) more than 2/255 apart in some channel, and
// the crop's mean radiance within 1% (float32 against double; paths that part at an edge).
void expectBackendsAgree(const SceneDesc& scene, const std::string& name, bool stratified = false) {
  Context* context = gpuContextOrSkip();
  if (!context) return;
  const int x0 = scene.width / 2 - 16, y0 = scene.height * 3 / 4 - 16;
  const PixelRect crop{x0, y0, x0 + 32, y0 + 32};

  PathOptions cpu;
  cpu.seed = 17;
  cpu.sampleCount = 4;
  cpu.crop = crop;
  cpu.stratified = stratified;
  RadianceImage onCpu = renderPathReference(scene, buildBvh(scene), cpu, nullptr);

  VulkanPathOptions gpu;
  gpu.seed = 17;
  gpu.sampleCount = 4;
  gpu.crop = crop;
  gpu.stratified = stratified;
  int before = context->validationMessages();
  RadianceImage onGpu = renderVulkanPath(*context, flatten(scene), gpu, nullptr, nullptr);
  EXPECT_EQ(context->validationMessages(), before) << "the Vulkan validation layer reported problems (see stderr)";

  ASSERT_EQ(onCpu.width, 32);
  ASSERT_EQ(onGpu.width, 32);
  EXPECT_TRUE(imagesClose(name, encoded(onGpu, scene.path.gamma), encoded(onCpu, scene.path.gamma), 2, 30));
  EXPECT_NEAR(mean(onGpu), mean(onCpu), 0.01 * mean(onCpu) + 1e-6);
}

class PathBackends : public ::testing::TestWithParam<const char*> {};

TEST_P(PathBackends, SameSeedNearlyTheSameImage) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  SceneDesc scene = parseSceneFile(*dir + "/scenes/" + GetParam() + ".test");
  expectBackendsAgree(scene, std::string("path-backends-") + testName(std::string(GetParam()).replace(3, 1, "_")));
}

// The project's own path-traced scene: no warning, and the two backends agree on it.
TEST(PathBackendsProjectScene, GiBoxParsesCleanlyAndBothBackendsAgree) {
  ParsedScene parsed = parseSceneFileWithWarnings(sourcePath("scenes/gi/box.test"));
  EXPECT_TRUE(parsed.warnings.empty()) << parsed.warnings.front().message;
  expectBackendsAgree(parsed.scene, "path-backends-gi-box");
}

// Emissive triangles and an ellipsoid (a rotated, non-uniformly scaled sphere) sampled as
// lights: both backends pick the same emitters and points with the same numbers, and weigh
// them (mis) alike.
TEST(PathBackendsEmitters, NextEventEstimationAndMisAgree) {
  for (NextEvent nee : {NextEvent::On, NextEvent::Mis}) {
    SceneDesc scene = emissiveSurfacesBox(64, 3);
    scene.path.nextEvent = nee;
    scene.path.sampling = Sampling::Brdf;
    scene.path.lightSamples = 4;
    scene.path.lightStratify = true;
    expectBackendsAgree(scene, nee == NextEvent::On ? "path-backends-emitters-nee" : "path-backends-emitters-mis");
  }
}

// Stratified samples (--sampler stratified): the same numbers on both backends (gpu_rng.h's
// rngStratify, shared), so the same agreement; and not the independent samples' image. With
// 8x8 strata (the scene's 64 samples), 3x3 (9) and 3x3 with 3 samples beyond them (12): strata
// counts that are not powers of two, where the permutation walks past the count.
TEST(PathBackendsStratified, BothBackendsStratifyAlike) {
  ParsedScene parsed = parseSceneFileWithWarnings(sourcePath("scenes/gi/box.test"));
  expectBackendsAgree(parsed.scene, "path-backends-gi-box-stratified", true);
  SceneDesc emitters = emissiveSurfacesBox(64, 3);
  emitters.path.nextEvent = NextEvent::Mis;
  emitters.path.sampling = Sampling::Brdf;
  expectBackendsAgree(emitters, "path-backends-emitters-stratified", true);
  for (int spp : {9, 12}) {
    SceneDesc box = parsed.scene;
    box.path.spp = spp;
    expectBackendsAgree(box, "path-backends-gi-box-stratified-" + std::to_string(spp), true);
    emitters.path.spp = spp;
    expectBackendsAgree(emitters, "path-backends-emitters-stratified-" + std::to_string(spp), true);
  }
  PathOptions o;
  o.seed = 17;
  o.sampleCount = 4;
  o.crop = PixelRect{0, 0, 16, 16};
  const Bvh bvh = buildBvh(parsed.scene);
  RadianceImage independent = renderPathReference(parsed.scene, bvh, o, nullptr);
  o.stratified = true;
  EXPECT_NE(renderPathReference(parsed.scene, bvh, o, nullptr).rgb, independent.rgb);
}

// The same through a whole render as the command line runs it (`--sampler stratified --spp 9`,
// the strata over the render's samples): both backends stratify, alike (neither image is its
// independent samples').
TEST(PathBackendsStratified, WholeRendersStratifyAlike) {
  VKRT_REQUIRE_GPU(ctx);
  auto render = [](Backend backend, bool stratified) {
    RenderRequest request;
    request.scenePath = sourcePath("scenes/gi/box.test");
    request.backend = backend;
    request.width = request.height = 64;
    request.crop = PixelRect{16, 24, 48, 56};
    request.spp = 9;
    request.seed = 5;
    request.stratified = stratified;
    ProgressBar quiet(false);
    RenderReport report;
    return renderSceneInMemory(request, quiet, report, false);
  };
  const RadianceImage cpu = render(Backend::Cpu, true), vulkan = render(Backend::Vulkan, true);
  ASSERT_EQ(vulkan.width, 32);
  EXPECT_NE(vulkan.rgb, render(Backend::Vulkan, false).rgb) << "the Vulkan render did not stratify";
  EXPECT_NE(cpu.rgb, render(Backend::Cpu, false).rgb) << "the CPU render did not stratify";
  EXPECT_TRUE(imagesClose("path-backends-whole-stratified", encoded(vulkan, 2.2), encoded(cpu, 2.2), 2, 30));
  EXPECT_NEAR(mean(vulkan), mean(cpu), 0.01 * mean(cpu) + 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Cse168, PathBackends,
                         ::testing::Values("hw2/analytic", "hw2/cornell", "hw2/direct3x3", "hw2/direct9", "hw2/dragon",
                                           "hw2/sphere", "hw3/cornellNEE", "hw3/cornellRR", "hw3/cornellSimple",
                                           "hw3/dragon", "hw4/cornellBRDF", "hw4/cornellCosine", "hw4/cornellMIS",
                                           "hw4/dragon", "hw4/ggx", "hw4/mis"),
                         [](const auto& p) { return testName(std::string(p.param).replace(3, 1, "_")); });

}  // namespace
