// The Vulkan backend's host side: upload, pipeline, band-by-band dispatch, readback.
#include "gpu/vulkan_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/scene_features.h"
#include "gpu/scene_upload.h"
#include "gpu/shader_variant.h"
#include "gpu/technique_bands.h"
#include "util/timing.h"

namespace vkrt {
namespace {

// Whether some material of the scene has a specular colour: highlights and mirror rays.
bool usesSpecular(const GpuScene& scene) {
  for (const gpu::GpuMaterial& m : scene.materials)
    if (m.specular.x != 0.0f || m.specular.y != 0.0f || m.specular.z != 0.0f) return true;
  return false;
}

// Whether the exactness cut-off can stop some path at least two bounces early: the first
// depth d at which a path of the largest weight (s^d) cannot change a byte any more, from the
// same bounds the shader uses, is below maxdepth - 1.
bool cutoffPays(const gpu::GpuCutoff& p, std::uint32_t maxDepth) {
  if (maxDepth < 2) return false;
  const float bound[3] = {p.bound.x, p.bound.y, p.bound.z};
  const float spec[3] = {p.specular.x, p.specular.y, p.specular.z};
  for (int c = 0; c < 3; ++c)   // a weight that never shrinks never gets cut (and maxdepth may be 10^6)
    if (spec[c] >= 1.0f && bound[c] > 0.0f) return false;
  for (std::uint32_t d = 1; d + 1 < maxDepth; ++d) {
    bool all = true;
    for (int c = 0; c < 3; ++c) {
      double s = spec[c], series = s < 1.0 ? 1.0 / (1.0 - s) : maxDepth;
      if (!std::isfinite(bound[c]) || std::pow(s, d) * bound[c] * series >= 1.0 / 255.0) all = false;
    }
    if (all) return true;
  }
  return false;
}

// A GpuCutoff that never cuts: no bound on what a hit sends (the reach is infinite) and no
// sign known.
gpu::GpuCutoff neverCut() {
  gpu::GpuCutoff c{};
  const float inf = std::numeric_limits<float>::infinity();
  c.bound.x = c.bound.y = c.bound.z = inf;
  c.bound.w = 0.0f;
  return c;
}

// The band layout of a Whitted render: one GpuWhittedState per invocation, shared by its
// pixels; the workgroups of a band each take a run of perInvocation adjacent 8x8 tiles.
BandLayout whittedLayout(const Context& context, const GpuScene& scene, const VulkanOptions& options) {
  // Sharing out pixels keeps a CPU's SIMD lanes busy; a GPU has lanes to spare for a pixel each.
  const bool cpuDevice = context.isCpuDevice();
  const std::uint32_t perInvocation = options.pixelsPerInvocation ? options.pixelsPerInvocation
                                      : cpuDevice                 ? gpu::kDefaultPixelsPerInvocation
                                                                  : 1u;
  return bandLayout(renderRegion(scene, options.crop), sizeof(gpu::GpuWhittedState), options.maxStateBytes,
                    perInvocation);
}

// The shader a Whitted render runs, decided before its buffers are made, and what it says of
// the render: whether the exactness cut-off cuts (compiled in, or told so at run time) and
// whether mirror rays are traced (the features' specular).
struct WhittedShader {
  TechniqueShader shader;
  bool cutoff = false;
  bool specular = true;
};

// `texelsFit`: SceneUpload::texelsFit, or texelsFitBeforeBvh for a pipeline made ahead;
// `eachPrimitiveOnce`: the BVH holds every primitive exactly once (before it is built, as
// prepareVulkanPipeline's caller says).
WhittedShader whittedShader(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                            const BandLayout& layout, bool texelsFit, bool eachPrimitiveOnce) {
  WhittedShader w;
  TechniqueShader& s = w.shader;
  s.testAll = testsEveryPrimitive(scene, options.testAll, eachPrimitiveOnce);
  const bool cpuDevice = context.isCpuDevice();
  const bool specular = usesSpecular(scene);
  // The exactness cut-off: forced, or where it pays. The general variant has it compiled in
  // and is told at run time whether to cut (push constants), so that it cuts exactly where
  // the specialised one does.
  w.cutoff = options.cutoff == Cutoff::On ||
             (options.cutoff == Cutoff::Auto && specular && cutoffPays(scene.cutoff, scene.maxDepth));
  // The rays this render will trace, about: a camera ray a pixel, a shadow ray a light, and
  // again for each mirror bounce (what ShaderVariant::Auto goes by).
  s.estimatedRays = static_cast<double>(layout.width) * layout.height *
                    (1.0 + static_cast<double>(scene.lights.size())) *
                    (1.0 + (specular ? std::min(scene.maxDepth, 4u) : 0u));
  // Bools as 0/1 (SPIR-V bool spec constants are 32 bits); every feature on in the general variant.
  auto specConstants = [&](bool general) {
    std::vector<std::uint32_t> spec(gpu::kSpecCount, 1u);
    if (!general) {
      setSharedFeatures(scene, spec);
      spec[gpu::kSpecHasSpecular] = specular;
    }
    spec[gpu::kSpecCutoff] = general || w.cutoff;
    spec[gpu::kSpecTestAll] = s.testAll;   // in the general variant too: a second general variant
    spec[gpu::kSpecWideBvh] = options.wideBvh;   // (the same)
    return spec;
  };
  // Texel reads where every scene buffer fits the device's texel-count limit and the device
  // allows the shader that many storage texel buffers.
  s.texelReads = chooseTexelReads(options.reads, SceneArrays::Whitted, texelsFit, context.properties().limits);
  const TechniqueSpirv& spirv = techniqueSpirv(options.shader);
  s.words = s.texelReads ? spirv.texelWords : spirv.words;
  s.bytes = s.texelReads ? spirv.texelBytes : spirv.bytes;
  s.specializedKey = variantKey(context.properties(), s.words, s.bytes, specConstants(false));
  s.general = options.variant == ShaderVariant::General ||
              (options.variant == ShaderVariant::Auto &&
               !autoTakesSpecialised(cpuDevice, s.estimatedRays, false, s.specializedKey));
  s.spec = specConstants(s.general);
  s.leftOut = leftOutNames(s.spec, {{gpu::kSpecHasSpecular, "specular (maxdepth 0)"}});
  if (!w.cutoff && !s.general) s.leftOut += std::string(s.leftOut.empty() ? "" : ", ") + "exactness cut-off";
  w.specular = s.spec[gpu::kSpecHasSpecular] != 0u;
  return w;
}

}  // namespace

void prepareVulkanPipeline(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           bool eachPrimitiveOnce) {
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const WhittedShader w = whittedShader(context, scene, options, whittedLayout(context, scene, options),
                                        texelsFitBeforeBvh(scene, SceneArrays::Whitted, maxTexels, options.wideBvh), eachPrimitiveOnce);
  prepareTechnique(context, w.shader, SceneArrays::Whitted, sizeof(gpu::GpuPushConstants));
}

RadianceImage renderVulkan(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           RayCounts* rays, VulkanTimings* timings) {
  VulkanTimings t;
  TechniqueBatch batch;
  batch.layout = whittedLayout(context, scene, options);
  checkShaderLimits(scene, options.wideBvh);

  auto t0 = std::chrono::steady_clock::now();
  const SceneUpload upload(context, scene, SceneArrays::Whitted);
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const WhittedShader w = whittedShader(context, scene, options, batch.layout, upload.texelsFit(maxTexels),
                                        bvhHoldsEachPrimitiveOnce(scene));
  t.uploadSeconds = secondsSince(t0);

  batch.arrays = SceneArrays::Whitted;
  batch.stateBytes = sizeof(gpu::GpuWhittedState);
  // Without a specular surface no mirror ray is ever traced.
  batch.params = renderParams(scene, batch.layout, w.specular ? scene.maxDepth : 0);
  batch.stepBudget = options.stepBudget;
  batch.firstDispatchSteps = kWhittedFirstDispatchSteps;
  batch.samples = 1;
  batch.imageSamples = options.sampleCount;   // the Whitted model: the mean of identical samples
  gpu::GpuPushConstants push{};
  push.camera = scene.camera;
  // A cut-off compiled in but not wanted is told never to cut (GpuCutoff: no bound).
  push.cutoff = w.cutoff ? scene.cutoff : neverCut();
  batch.push = techniquePush(push);
  batch.stop = options.stop;
  batch.progress = options.progress;
  batch.rows = options.rows;
  return renderTechniqueBands(context, upload, w.shader, batch, rays, timings, t);
}

}  // namespace vkrt
