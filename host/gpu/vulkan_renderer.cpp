// The Vulkan backend's host side: upload, pipeline, band-by-band dispatch, readback.
#include "gpu/vulkan_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>

#include "gpu/band_buffers.h"
#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/compute_pipeline.h"
#include "gpu/scene_upload.h"
#include "timing.h"
#include "raytrace.comp.h"         // kRaytraceSpirv: the shader, compiled at build time
#include "raytrace_texel.comp.h"   // kRaytraceTexelSpirv: the same with VKRT_TEXEL_READS

namespace vkrt {
namespace {

// Which features the scene uses; the shader is specialised to them (all on when not
// specializing). Also says, for --stats, what was left out.
struct Features {
  bool triangles = true, spheres = true, smoothNormals = true, pointLights = true, directionalLights = true,
       attenuation = true, specular = true;
  std::string leftOut;
};

Features sceneFeatures(const GpuScene& scene, bool specialize) {
  Features f;
  if (!specialize) return f;
  f.triangles = !scene.triangles.empty();
  f.spheres = !scene.spheres.empty();
  f.smoothNormals = !scene.triangleNormals.empty();
  f.pointLights = f.directionalLights = f.attenuation = f.specular = false;
  for (const gpu::GpuLight& l : scene.lights) {
    bool point = l.positionOrDirection.w == gpu::kPointLight;
    (point ? f.pointLights : f.directionalLights) = true;
    if (point && (l.attenuation.x != 1.0f || l.attenuation.y != 0.0f || l.attenuation.z != 0.0f)) f.attenuation = true;
  }
  for (const gpu::GpuMaterial& m : scene.materials)
    if (m.specular.x != 0.0f || m.specular.y != 0.0f || m.specular.z != 0.0f) f.specular = true;
  auto note = [&f](bool used, const char* name) {
    if (!used) f.leftOut += (f.leftOut.empty() ? "" : ", ") + std::string(name);
  };
  note(f.triangles, "triangles");
  note(f.spheres, "spheres");
  note(f.smoothNormals, "smooth normals");
  note(f.pointLights, "point lights");
  note(f.directionalLights, "directional lights");
  note(f.attenuation, "attenuation");
  note(f.specular, "specular (maxdepth 0)");
  return f;
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

}  // namespace

RadianceImage renderVulkan(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           RayCounts* rays, VulkanTimings* timings) {
  VulkanTimings t;
  // Sharing out pixels keeps a CPU's SIMD lanes busy; a GPU has lanes to spare for a pixel each.
  const bool cpuDevice = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const std::uint32_t perInvocation = options.pixelsPerInvocation ? options.pixelsPerInvocation
                                      : cpuDevice                 ? gpu::kDefaultPixelsPerInvocation
                                                                  : 1u;
  // One GpuWhittedState per invocation, shared by its perInvocation pixels; the workgroups of a
  // band each take a run of perInvocation adjacent 8x8 tiles.
  const BandLayout layout = bandLayout(renderRegion(scene, options.crop), sizeof(gpu::GpuWhittedState),
                                       options.maxStateBytes, perInvocation);
  const std::uint32_t width = layout.width, height = layout.height;
  checkShaderLimits(scene);

  auto t0 = std::chrono::steady_clock::now();
  const Features features = sceneFeatures(scene, options.specialize);
  t.leftOut = features.leftOut;
  // Without a specular surface no mirror ray is ever traced.
  const gpu::GpuRenderParams params = renderParams(scene, layout, features.specular ? scene.maxDepth : 0);
  const SceneUpload upload(context, scene, SceneArrays::Whitted);
  BandBuffers band(context, layout, layout.invocations() * sizeof(gpu::GpuWhittedState), params, options.stepBudget,
                   kWhittedFirstDispatchSteps);
  t.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  std::vector<std::uint32_t> spec(gpu::kSpecCount);   // bools as 0/1 (SPIR-V bool spec constants are 32 bits)
  spec[gpu::kSpecHasTriangles] = features.triangles;
  spec[gpu::kSpecHasSpheres] = features.spheres;
  spec[gpu::kSpecHasSmoothNormals] = features.smoothNormals;
  spec[gpu::kSpecHasPointLights] = features.pointLights;
  spec[gpu::kSpecHasDirectionalLights] = features.directionalLights;
  spec[gpu::kSpecHasAttenuation] = features.attenuation;
  spec[gpu::kSpecHasSpecular] = features.specular;
  // Unspecialized (everything compiled in), Auto means on.
  const bool cutoff = options.cutoff == Cutoff::On ||
                      (options.cutoff == Cutoff::Auto &&
                       (!options.specialize || (features.specular && cutoffPays(scene.cutoff, scene.maxDepth))));
  spec[gpu::kSpecCutoff] = cutoff;
  if (!cutoff) t.leftOut += std::string(t.leftOut.empty() ? "" : ", ") + "exactness cut-off";
  // Texel reads where every scene buffer fits the device's texel-count limit.
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  t.texelReads = chooseTexelReads(options.reads, upload.texelsFit(maxTexels), maxTexels);
  ShaderBindings bindings(gpu::kBindingCount);
  upload.bind(bindings, t.texelReads);
  band.bind(bindings);
  ComputePipeline pipeline(context, t.texelReads ? kRaytraceTexelSpirv : kRaytraceSpirv,
                           t.texelReads ? sizeof(kRaytraceTexelSpirv) : sizeof(kRaytraceSpirv), bindings.types,
                           spec, sizeof(gpu::GpuPushConstants));
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
  push.cutoff = scene.cutoff;
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
  if (rays) *rays = counted;
  if (timings) *timings = t;
  return image;
}

}  // namespace vkrt
