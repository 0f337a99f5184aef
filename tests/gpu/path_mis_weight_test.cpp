// The MIS weights of nexteventestimation mis (doc/path-tracing.md, "Estimators": the power
// heuristic, beta = 2). An estimator that weighs both strategies by another heuristic that
// still sums to one (the balance heuristic) converges to the same image, so the strategy
// tests cannot see it: the weight functions of both backends are checked against the closed
// form, and each backend's use of them at every site (a light sample, a sampled ray hitting
// a light; quad lights and emitters) path by path against the other backend's at one seed.
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/path_brdf.h"
#include "cpu/path_reference.h"
#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/vulkan_path_renderer.h"
#include "mis_weight_probe.comp.h"
#include "path_scenes.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

struct Pair {
  double pdfThis, pdfOther;
};
// Densities as the integrators meet them: equal, a few times apart, orders of magnitude
// apart (a Phong lobe of shininess 1000 against a large light), and far beyond float32's
// square (1e20: the weight must still be 0 or 1, not NaN).
const Pair kPairs[] = {{1, 1},       {1, 2},      {2, 1},      {0.3, 0.9},  {5, 0.5}, {0.159, 1.7},
                       {1e-3, 10},   {160, 0.25}, {1e3, 1e-3}, {1e-20, 1e20}, {1e20, 1e-20}, {7, 0}};

double closedForm(const Pair& p) { return p.pdfThis * p.pdfThis / (p.pdfThis * p.pdfThis + p.pdfOther * p.pdfOther); }

TEST(PathMisWeight, CpuWeightIsThePowerHeuristic) {
  for (const Pair& p : kPairs) {
    const double w = powerHeuristic(p.pdfThis, p.pdfOther);
    EXPECT_NEAR(w, closedForm(p), 1e-15) << p.pdfThis << " against " << p.pdfOther;
    EXPECT_NEAR(w + powerHeuristic(p.pdfOther, p.pdfThis), 1.0, 1e-15) << p.pdfThis << " against " << p.pdfOther;
  }
  EXPECT_EQ(powerHeuristic(0.0, 0.0), 0.0);
}

TEST(PathMisWeight, ShaderWeightIsThePowerHeuristic) {
  VKRT_REQUIRE_GPU(context);
  std::vector<float> pairs;
  for (const Pair& p : kPairs) {
    pairs.push_back(static_cast<float>(p.pdfThis));
    pairs.push_back(static_cast<float>(p.pdfOther));
  }
  Buffer in = Buffer::withContents(*context, pairs);
  Buffer out(*context, std::size(kPairs) * sizeof(float), true);
  ComputePipeline probe(*context, kMisWeightProbeSpirv, sizeof(kMisWeightProbeSpirv),
                        {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {}, 0);
  probe.bind(0, in);
  probe.bind(1, out);
  probe.run(nullptr, 1);
  const auto* weights = static_cast<const float*>(out.mapped());
  for (std::size_t i = 0; i < std::size(kPairs); ++i)
    EXPECT_NEAR(weights[i], closedForm(kPairs[i]), 1e-6) << kPairs[i].pdfThis << " against " << kPairs[i].pdfOther;
  EXPECT_EQ(context->validationMessages(), 0);
}

// One seed, 4 samples per pixel: the CPU reference (double) and the shader (float32) follow
// the same paths, so each pixel's radiance agrees to float rounding, except where a float32
// ray and its double twin part at an edge. Tolerance: |gpu - cpu| <= 1e-3 (|cpu| + 0.01) in
// every channel, in all but 3% of the pixels (30 of 1024). A weight that differs at one site
// on one backend (another heuristic, swapped densities) moves most pixels of these scenes by
// more than 1%.
void expectSameWeightsOnBothBackends(const SceneDesc& scene, const std::string& name) {
  Context* context = gpuContextOrSkip();
  if (!context) return;
  PathOptions cpu;
  cpu.seed = 23;
  cpu.sampleCount = 4;
  const RadianceImage onCpu = renderPathReference(scene, buildBvh(scene), cpu, nullptr);
  VulkanPathOptions gpu;
  gpu.seed = 23;
  gpu.sampleCount = 4;
  const int before = context->validationMessages();
  RayCounts rays;
  const RadianceImage onGpu = renderVulkanPath(*context, flatten(scene), gpu, &rays, nullptr);
  EXPECT_EQ(context->validationMessages(), before);
  EXPECT_EQ(rays.nonFinite, 0u);
  ASSERT_EQ(onCpu.rgb.size(), onGpu.rgb.size());
  int apart = 0, lit = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < onCpu.rgb.size(); i += 3) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      const double a = onGpu.rgb[i + c], b = onCpu.rgb[i + c];
      const double relative = std::abs(a - b) / (std::abs(b) + 0.01);
      worst = std::max(worst, relative);
      differs = differs || relative > 1e-3;
      lit += c == 0 && b > 0.01;
    }
    apart += differs;
  }
  const int pixels = static_cast<int>(onCpu.rgb.size() / 3);
  EXPECT_GT(lit, pixels / 2) << name << ": the scene should be mostly lit";
  EXPECT_LE(apart, 3 * pixels / 100) << name << ": " << apart << " of " << pixels
                                 << " pixels differ by more than 1e-3 relative (worst " << worst << ")";
}

// Quad lights: a large light close above a Phong and a GGX floor (both strategies matter),
// direct lighting and two more bounces.
TEST(PathMisWeight, BothBackendsWeighQuadLightPathsAlike) {
  for (int depth : {1, 3}) {
    SceneDesc scene = glossyFloorUnderLargeLight(32);
    scene.maxDepth = depth;
    scene.path.nextEvent = NextEvent::Mis;
    scene.path.sampling = Sampling::Brdf;
    expectSameWeightsOnBothBackends(scene, "quad light, maxdepth " + std::to_string(depth));
  }
}

// Emissive triangles and an ellipsoid sampled as lights.
TEST(PathMisWeight, BothBackendsWeighEmitterPathsAlike) {
  SceneDesc scene = emissiveSurfacesBox(32, 2);
  scene.path.nextEvent = NextEvent::Mis;
  scene.path.sampling = Sampling::Brdf;
  expectSameWeightsOnBothBackends(scene, "emitters");
}

}  // namespace
