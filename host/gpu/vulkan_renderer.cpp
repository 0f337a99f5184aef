// The Vulkan backend's host side: upload, pipeline, band-by-band dispatch, readback.
#include "gpu/vulkan_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>

#include "gpu/band_dispatch.h"
#include "gpu/compute_pipeline.h"
#include "errors.h"
#include "gpu/device_error.h"
#include "gpu/tile_order.h"
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
bool cutoffPays(const gpu::GpuPushConstants& p, std::uint32_t maxDepth) {
  if (maxDepth < 2) return false;
  const float bound[3] = {p.cutoffBound.x, p.cutoffBound.y, p.cutoffBound.z};
  const float spec[3] = {p.cutoffSpecular.x, p.cutoffSpecular.y, p.cutoffSpecular.z};
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
  // The pixels computed: the whole image or the crop; bands and tiles cover these only.
  const PixelRect region = options.crop ? *options.crop
                                        : PixelRect{0, 0, static_cast<int>(scene.width), static_cast<int>(scene.height)};
  const auto width = static_cast<std::uint32_t>(region.width()), height = static_cast<std::uint32_t>(region.height());
  const std::uint32_t tile = gpu::kWorkgroupSize, groupSize = tile * tile;
  // Sharing out pixels keeps a CPU's SIMD lanes busy; a GPU has lanes to spare for a pixel each.
  const bool cpuDevice = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const std::uint32_t perInvocation = options.pixelsPerInvocation ? options.pixelsPerInvocation
                                      : cpuDevice                 ? gpu::kDefaultPixelsPerInvocation
                                                                  : 1u;
  // Band height: a multiple of the tile, and a state buffer (one GpuPathState per invocation)
  // within maxStateBytes.
  std::size_t rowsByMemory = options.maxStateBytes * perInvocation / (sizeof(gpu::GpuPathState) * width);
  std::uint32_t bandHeight = static_cast<std::uint32_t>(std::max<std::size_t>(tile, rowsByMemory / tile * tile));
  bandHeight = std::min(bandHeight, (height + tile - 1) / tile * tile);
  // The workgroups of a band: each takes a run of perInvocation adjacent 8x8 tiles.
  const std::size_t bandPixels = std::size_t{width} * bandHeight;
  const std::uint32_t tilesX = (width + tile - 1) / tile;
  const std::uint32_t tilesInBand = tilesX * (bandHeight / tile);
  const std::uint32_t groups = (tilesInBand + perInvocation - 1) / perInvocation;

  // The shader packs a leaf's first primRef into 28 bits (kStackFirstMask).
  if (scene.bvh.primRefs.size() > gpu::kStackFirstMask)
    throw DeviceError("the scene has " + std::to_string(scene.bvh.primRefs.size()) +
                      " primitives; the Vulkan backend takes at most " + std::to_string(gpu::kStackFirstMask) +
                      " (--backend cpu has no such limit)");

  auto t0 = std::chrono::steady_clock::now();
  Buffer triangles = Buffer::withContents(context, scene.triangles);
  Buffer normals = Buffer::withContents(context, scene.triangleNormals);
  Buffer spheres = Buffer::withContents(context, scene.spheres);
  Buffer lights = Buffer::withContents(context, scene.lights);
  Buffer materials = Buffer::withContents(context, scene.materials);
  Buffer nodes = Buffer::withContents(context, scene.bvh.nodes);
  Buffer primRefs = Buffer::withContents(context, scene.bvh.primRefs);
  Buffer pixels(context, bandPixels * sizeof(gpu::vec4), true);
  Buffer states(context, std::size_t{groups} * groupSize * sizeof(gpu::GpuPathState));
  Buffer counters(context, sizeof(gpu::GpuCounters), true);
  std::memset(counters.mapped(), 0, sizeof(gpu::GpuCounters));
  t.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  const Features features = sceneFeatures(scene, options.specialize);
  t.leftOut = features.leftOut;
  gpu::GpuRenderParams params{};
  params.width = width;
  params.height = height;
  // Without a specular surface no mirror ray is ever traced.
  params.maxDepth = features.specular ? scene.maxDepth : 0;
  params.lightCount = static_cast<std::uint32_t>(scene.lights.size());
  params.stepBudget = options.stepBudget ? options.stepBudget
                                         : firstStepBudget(gpu::kDefaultStepBudget,
                                                           std::uint64_t{groups} * groupSize, cpuDevice,
                                                           kWhittedFirstDispatchSteps);
  params.bandHeight = bandHeight;
  params.tilesX = tilesX;
  params.tileOrderStride = scatterStride(groups);   // the order of the workgroups' runs of tiles
  params.primCount = static_cast<std::uint32_t>(scene.bvh.primRefs.size());
  const gpu::GpuBvhNode& root = scene.bvh.nodes[0];
  params.originX = static_cast<std::uint32_t>(region.x0);
  params.originY = static_cast<std::uint32_t>(region.y0);
  params.fullWidth = scene.width;
  params.fullHeight = scene.height;
  params.rootEntry = root.primCount > 0 ? gpu::kStackLeafBit | root.primCount << gpu::kStackCountShift |
                                              root.leftOrFirst
                                        : root.leftOrFirst;
  // The shader's traversal stack has a fixed size; the builder keeps the BVH within it.
  if (scene.bvh.depth + 1 > static_cast<int>(gpu::kTraversalStackSize))
    throw InternalError("BVH depth " + std::to_string(scene.bvh.depth) + " exceeds the traversal stack");
  Buffer paramsBuffer(context, sizeof params);
  std::memcpy(paramsBuffer.mapped(), &params, sizeof params);
  StepPace pace;
  if (!options.stepBudget) pace = {&static_cast<gpu::GpuRenderParams*>(paramsBuffer.mapped())->stepBudget, gpu::kDefaultStepBudget};

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
                       (!options.specialize || (features.specular && cutoffPays(scene.push, scene.maxDepth))));
  spec[gpu::kSpecCutoff] = cutoff;
  if (!cutoff) t.leftOut += std::string(t.leftOut.empty() ? "" : ", ") + "exactness cut-off";
  // Texel reads where every scene buffer fits the device's texel-count limit.
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const Buffer* sceneBuffers[] = {&triangles, &normals, &spheres, &lights, &materials, &nodes};
  bool texelsFit = primRefs.size() / 4 <= maxTexels;
  for (const Buffer* b : sceneBuffers) texelsFit = texelsFit && b->size() / 16 <= maxTexels;
  t.texelReads = options.reads == SceneReads::Texel || (options.reads == SceneReads::Auto && texelsFit);
  if (t.texelReads && !texelsFit)
    throw DeviceError("the scene is too large for texel-buffer reads on this device (limit " +
                      std::to_string(maxTexels) + " texels); use storage-buffer reads (--reads storage)");
  std::vector<VkDescriptorType> types(gpu::kBindingCount, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  if (t.texelReads)
    std::fill(types.begin(), types.begin() + gpu::kBindingPixels, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
  types[gpu::kBindingParams] = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  ComputePipeline pipeline(context, t.texelReads ? kRaytraceTexelSpirv : kRaytraceSpirv,
                           t.texelReads ? sizeof(kRaytraceTexelSpirv) : sizeof(kRaytraceSpirv), types, spec,
                           sizeof(gpu::GpuPushConstants));
  const Buffer* bound[gpu::kBindingCount] = {};
  bound[gpu::kBindingTriangles] = &triangles;
  bound[gpu::kBindingTriangleNormals] = &normals;
  bound[gpu::kBindingSpheres] = &spheres;
  bound[gpu::kBindingLights] = &lights;
  bound[gpu::kBindingMaterials] = &materials;
  bound[gpu::kBindingBvhNodes] = &nodes;
  bound[gpu::kBindingPrimRefs] = &primRefs;
  bound[gpu::kBindingPixels] = &pixels;
  bound[gpu::kBindingPathStates] = &states;
  bound[gpu::kBindingCounters] = &counters;
  bound[gpu::kBindingParams] = &paramsBuffer;
  for (std::uint32_t b = 0; b < gpu::kBindingCount; ++b) {
    if (b == gpu::kBindingParams)
      pipeline.bindUniform(b, *bound[b]);
    else if (!t.texelReads || b >= gpu::kBindingPixels)
      pipeline.bind(b, *bound[b]);
    else if (b == gpu::kBindingPrimRefs)
      pipeline.bindTexels(b, *bound[b], VK_FORMAT_R32_UINT, 4);
    else
      pipeline.bindTexels(b, *bound[b], VK_FORMAT_R32G32B32A32_UINT, 16);
  }
  t.pipelineSeconds = secondsSince(t0);

  // The whole image, or (streaming to options.rows) one band's rows at a time.
  RadianceImage image =
      options.rows ? RadianceImage() : RadianceImage(static_cast<int>(width), static_cast<int>(height));
  image.samples = options.sampleCount;   // the Whitted model: the mean of identical samples
  RadianceImage band;
  band.samples = options.sampleCount;
  gpu::GpuPushConstants push = scene.push;
  RayCounts counted;
  for (std::uint32_t y0 = 0; y0 < height; y0 += bandHeight) {
    push.bandY0 = y0;
    if (!dispatchBand(pipeline, &push, push.resume, y0, groups, counters, options.stop, t, counted, &pace))
      return image;

    t0 = std::chrono::steady_clock::now();
    std::uint32_t rows = std::min(bandHeight, height - y0);
    const auto* mapped = static_cast<const float*>(pixels.mapped());   // vec4 per pixel
    if (options.rows && band.height != static_cast<int>(rows))
      band = RadianceImage(static_cast<int>(width), static_cast<int>(rows));
    for (std::uint32_t y = 0; y < rows; ++y) {
      float* out = options.rows ? band.pixel(0, static_cast<int>(y)) : image.pixel(0, static_cast<int>(y0 + y));
      const float* in = mapped + std::size_t{y} * width * 4;
      for (std::uint32_t x = 0; x < width; ++x) {
        out[3 * x] = in[4 * x];
        out[3 * x + 1] = in[4 * x + 1];
        out[3 * x + 2] = in[4 * x + 2];
      }
    }
    t.readbackSeconds += secondsSince(t0);
    if (options.rows) options.rows(static_cast<int>(y0), band);
    if (options.progress) options.progress(std::uint64_t{y0 + rows} * width, std::uint64_t{height} * width);
  }
  if (rays) {
    *rays = counted;
    rays->primary = std::uint64_t{width} * height;
  }
  if (timings) *timings = t;
  return image;
}

}  // namespace vkrt
