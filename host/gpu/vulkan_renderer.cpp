// The Vulkan backend's host side: upload, pipeline, band-by-band dispatch, readback.
#include "gpu/vulkan_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "gpu/band_buffers.h"
#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/compute_pipeline.h"
#include "gpu/scene_features.h"
#include "gpu/scene_upload.h"
#include "gpu/shader_variant.h"
#include "timing.h"
#include "raytrace.comp.h"         // kRaytraceSpirv: the shader, compiled at build time
#include "raytrace_texel.comp.h"   // kRaytraceTexelSpirv: the same with VKRT_TEXEL_READS

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

// The shader a Whitted render runs, decided before its buffers are made: the module (texel or
// storage reads), the variant and its specialization constants, and what --stats says of them.
struct WhittedShader {
  bool cutoff = false;     // the exactness cut-off cuts (compiled in, or told so at run time)
  bool specular = true;    // mirror rays are traced (the features' specular)
  bool testAll = false;    // rays test every primitive (testsEveryPrimitive), specialised or general
  bool texelReads = false, general = false;
  const std::uint32_t* spirv = nullptr;
  std::size_t spirvBytes = 0;
  std::vector<std::uint32_t> spec;
  std::uint64_t specializedKey = 0;   // the specialised variant's, general or not
  double estimatedRays = 0;
  std::string leftOut;
};

// `texelsFit`: SceneUpload::texelsFit, or texelsFitBeforeBvh for a pipeline made ahead;
// `eachPrimitiveOnce`: the BVH holds every primitive exactly once (before it is built, as
// prepareVulkanPipeline's caller says).
WhittedShader whittedShader(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                            const BandLayout& layout, bool texelsFit, bool eachPrimitiveOnce) {
  WhittedShader w;
  w.testAll = testsEveryPrimitive(scene, options.testAll, eachPrimitiveOnce);
  const bool cpuDevice = context.isCpuDevice();
  const bool specular = usesSpecular(scene);
  // The exactness cut-off: forced, or where it pays. The general variant has it compiled in
  // and is told at run time whether to cut (push constants), so that it cuts exactly where
  // the specialised one does.
  w.cutoff = options.cutoff == Cutoff::On ||
             (options.cutoff == Cutoff::Auto && specular && cutoffPays(scene.cutoff, scene.maxDepth));
  // The rays this render will trace, about: a camera ray a pixel, a shadow ray a light, and
  // again for each mirror bounce (what ShaderVariant::Auto goes by).
  w.estimatedRays = static_cast<double>(layout.width) * layout.height *
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
    spec[gpu::kSpecTestAll] = w.testAll;   // in the general variant too: a second general variant
    return spec;
  };
  // Texel reads where every scene buffer fits the device's texel-count limit and the device
  // allows the shader that many storage texel buffers.
  w.texelReads = chooseTexelReads(options.reads, SceneArrays::Whitted, texelsFit, context.properties().limits);
  w.spirv = w.texelReads ? kRaytraceTexelSpirv : kRaytraceSpirv;
  w.spirvBytes = w.texelReads ? sizeof(kRaytraceTexelSpirv) : sizeof(kRaytraceSpirv);
  w.specializedKey = variantKey(context.properties(), w.spirv, w.spirvBytes, specConstants(false));
  w.general = options.variant == ShaderVariant::General ||
              (options.variant == ShaderVariant::Auto &&
               !autoTakesSpecialised(cpuDevice, w.estimatedRays, false, w.specializedKey));
  w.spec = specConstants(w.general);
  w.leftOut = leftOutNames(w.spec, {{gpu::kSpecHasSpecular, "specular (maxdepth 0)"}});
  if (!w.cutoff && !w.general) w.leftOut += std::string(w.leftOut.empty() ? "" : ", ") + "exactness cut-off";
  w.specular = w.spec[gpu::kSpecHasSpecular] != 0u;
  return w;
}

}  // namespace

void prepareVulkanPipeline(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           bool eachPrimitiveOnce) {
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const WhittedShader w = whittedShader(context, scene, options, whittedLayout(context, scene, options),
                                        texelsFitBeforeBvh(scene, SceneArrays::Whitted, maxTexels), eachPrimitiveOnce);
  ComputePipeline::prepare(context, w.spirv, w.spirvBytes, ShaderBindings(SceneArrays::Whitted, w.texelReads).types,
                           w.spec, sizeof(gpu::GpuPushConstants));
}

RadianceImage renderVulkan(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           RayCounts* rays, VulkanTimings* timings) {
  VulkanTimings t;
  const BandLayout layout = whittedLayout(context, scene, options);
  const std::uint32_t width = layout.width, height = layout.height;
  checkShaderLimits(scene);

  auto t0 = std::chrono::steady_clock::now();
  const SceneUpload upload(context, scene, SceneArrays::Whitted);
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const WhittedShader shader = whittedShader(context, scene, options, layout, upload.texelsFit(maxTexels),
                                             bvhHoldsEachPrimitiveOnce(scene));
  t.testedAll = shader.testAll;
  t.texelReads = shader.texelReads;
  t.general = shader.general;
  t.estimatedRays = shader.estimatedRays;
  t.leftOut = shader.leftOut;
  // Without a specular surface no mirror ray is ever traced.
  const gpu::GpuRenderParams params = renderParams(scene, layout, shader.specular ? scene.maxDepth : 0);
  BandBuffers band(context, layout, layout.invocations() * sizeof(gpu::GpuWhittedState), params, options.stepBudget,
                   kWhittedFirstDispatchSteps);
  t.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  ShaderBindings bindings(SceneArrays::Whitted, t.texelReads);
  upload.bind(bindings);
  band.bind(bindings);
  ComputePipeline pipeline(context, shader.spirv, shader.spirvBytes, bindings.types, shader.spec,
                           sizeof(gpu::GpuPushConstants));
  bindings.bindTo(pipeline);
  t.pipelineSeconds = secondsSince(t0);

  // The whole image, or (streaming to options.rows) one band's rows at a time.
  RadianceImage image =
      options.rows ? RadianceImage() : RadianceImage(static_cast<int>(width), static_cast<int>(height));
  image.samples = options.sampleCount;   // the Whitted model: the mean of identical samples
  RadianceImage rowsImage;
  rowsImage.samples = options.sampleCount;
  gpu::GpuPushConstants push{};
  push.camera = scene.camera;
  // A cut-off compiled in but not wanted is told never to cut (GpuCutoff: no bound).
  push.cutoff = shader.cutoff ? scene.cutoff : neverCut();
  BandHooks hooks{options.stop, options.progress,
                  [&](std::uint32_t y0, std::uint32_t rows) {
                    if (!options.rows) return band.readRows(rows, 1.0f, image, static_cast<int>(y0));
                    if (rowsImage.height != static_cast<int>(rows))
                      rowsImage = RadianceImage(static_cast<int>(width), static_cast<int>(rows));
                    band.readRows(rows, 1.0f, rowsImage, 0);
                  },
                  {}};
  if (options.rows) hooks.after = [&](std::uint32_t y0, std::uint32_t) { options.rows(static_cast<int>(y0), rowsImage); };
  RayCounts counted;
  if (!band.run(pipeline, &push, push.bandY0, push.resume, layout, 1, hooks, t, counted)) return image;
  if (!t.general) recordVariantCompiled(shader.specializedKey);
  if (rays) *rays = counted;
  if (timings) *timings = t;
  return image;
}

}  // namespace vkrt
