// The path integrators' host side: upload, pipeline, band-by-band dispatch until no pixel is
// left suspended, readback of the float sums as their mean.
#include "gpu/vulkan_path_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>

#include "errors.h"
#include "gpu/band_dispatch.h"
#include "gpu/compute_pipeline.h"
#include "gpu/device_error.h"
#include "gpu/tile_order.h"
#include "pathtrace.comp.h"         // kPathtraceSpirv: the shader, compiled at build time
#include "pathtrace_texel.comp.h"   // kPathtraceTexelSpirv: the same with VKRT_TEXEL_READS
#include "timing.h"

namespace vkrt {
namespace {

static_assert(sizeof(gpu::GpuQuadLight) == 16 * gpu::kQuadLightTexels, "the texel view of a quad light");

// The features pathtrace.comp is specialised to (all on when not specializing), and what was
// left out, for --stats; the integrator settings (kPathSpecFromParams when not specializing);
// and whether rays test every primitive instead of walking the BVH (either way).
std::vector<std::uint32_t> pathFeatures(const GpuScene& scene, std::uint32_t jitter, bool specialize, bool testAll,
                                        std::string& leftOut) {
  std::vector<std::uint32_t> spec(gpu::kPathSpecCount, 1u);   // bools as 0/1 (32-bit spec constants)
  for (std::uint32_t i = gpu::kPathSpecIntegrator; i <= gpu::kPathSpecJitter; ++i) spec[i] = gpu::kPathSpecFromParams;
  spec[gpu::kPathSpecTestAll] = testAll;
  if (!specialize) return spec;
  bool point = false, directional = false, attenuation = false, ggx = false;
  for (const gpu::GpuLight& l : scene.lights) {
    bool isPoint = l.positionOrDirection.w == gpu::kPointLight;
    (isPoint ? point : directional) = true;
    if (isPoint && (l.attenuation.x != 1.0f || l.attenuation.y != 0.0f || l.attenuation.z != 0.0f)) attenuation = true;
  }
  for (const gpu::GpuMaterial& m : scene.materials) ggx = ggx || m.ambient.w == gpu::kBrdfGgx;
  spec[gpu::kSpecHasTriangles] = !scene.triangles.empty();
  spec[gpu::kSpecHasSpheres] = !scene.spheres.empty();
  spec[gpu::kSpecHasSmoothNormals] = !scene.triangleNormals.empty();
  spec[gpu::kSpecHasPointLights] = point;
  spec[gpu::kSpecHasDirectionalLights] = directional;
  spec[gpu::kSpecHasAttenuation] = attenuation;
  spec[gpu::kPathSpecHasQuadLights] = !scene.quadLights.empty();
  spec[gpu::kPathSpecHasGgx] = ggx;
  spec[gpu::kPathSpecHasEmitters] = !scene.emitters.empty();
  // The integrator settings (a shader per combination; each is compiled once and cached).
  spec[gpu::kPathSpecIntegrator] = scene.path.integrator;
  spec[gpu::kPathSpecNextEvent] = scene.path.nextEvent;
  spec[gpu::kPathSpecSampling] = scene.path.sampling;
  spec[gpu::kPathSpecRussianRoulette] = scene.path.russianRoulette;
  spec[gpu::kPathSpecStratified] = scene.path.lightStrata > 0 ? 1u : 0u;
  spec[gpu::kPathSpecJitter] = jitter;
  const char* names[gpu::kPathSpecHasGgx + 1] = {"triangles",   "spheres",            "smooth normals", "point lights",
                                            "directional lights", "attenuation", "quad lights",    "ggx"};
  for (std::uint32_t i = 0; i <= gpu::kPathSpecHasGgx; ++i)
    if (!spec[i]) leftOut += (leftOut.empty() ? "" : ", ") + std::string(names[i]);
  if (!spec[gpu::kPathSpecHasEmitters]) leftOut += (leftOut.empty() ? "" : ", ") + std::string("emissive surfaces");
  return spec;
}

}  // namespace

RadianceImage renderVulkanPath(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                               RayCounts* rays, VulkanTimings* timings) {
  VulkanTimings t;
  if (scene.path.integrator == gpu::kIntegratorRaytracer)
    throw InternalError("renderVulkanPath called for the raytracer integrator (renderVulkan renders it)");
  const PixelRect region = options.crop ? *options.crop
                                        : PixelRect{0, 0, static_cast<int>(scene.width), static_cast<int>(scene.height)};
  const auto width = static_cast<std::uint32_t>(region.width()), height = static_cast<std::uint32_t>(region.height());
  const std::uint32_t tile = gpu::kWorkgroupSize;
  const std::uint32_t samples = options.sampleCount ? options.sampleCount : scene.spp;
  const std::uint32_t renderSpp = options.renderSpp ? options.renderSpp : scene.spp;

  // Band height: a multiple of the tile, and a state buffer within maxStateBytes.
  std::size_t rowsByMemory = options.maxStateBytes / (sizeof(gpu::GpuPathTracerState) * width);
  std::uint32_t bandHeight = static_cast<std::uint32_t>(std::max<std::size_t>(tile, rowsByMemory / tile * tile));
  bandHeight = std::min(bandHeight, (height + tile - 1) / tile * tile);
  const std::uint32_t tilesX = (width + tile - 1) / tile;
  const std::uint32_t tilesInBand = tilesX * (bandHeight / tile);

  if (scene.bvh.primRefs.size() > gpu::kStackFirstMask)
    throw DeviceError("the scene has " + std::to_string(scene.bvh.primRefs.size()) +
                      " primitives; the Vulkan backend takes at most " + std::to_string(gpu::kStackFirstMask) +
                      " (--backend cpu has no such limit)");
  // A vertex's random numbers must stay within its stride of dimensions (gpu_types.h): two
  // per quad-light sample, and with emitters two more and a pick per light sample.
  const std::uint64_t lightSlots = std::uint64_t{scene.path.quadLightCount} * scene.path.lightSamples * 2 +
                                   (scene.emitters.empty() ? 0u : std::uint64_t{scene.path.lightSamples} * 3);
  if (gpu::kRngSlotLightBase + lightSlots > gpu::kRngBounceStride)
    throw DeviceError("the light samples per vertex need " + std::to_string(lightSlots) +
                      " random numbers; the generator's dimensions allow at most " +
                      std::to_string(gpu::kRngBounceStride - gpu::kRngSlotLightBase) +
                      " (fewer quad lights or lightsamples)");
  if (scene.bvh.depth + 1 > static_cast<int>(gpu::kTraversalStackSize))
    throw InternalError("BVH depth " + std::to_string(scene.bvh.depth) + " exceeds the traversal stack");

  auto t0 = std::chrono::steady_clock::now();
  Buffer triangles = Buffer::withContents(context, scene.triangles);
  Buffer normals = Buffer::withContents(context, scene.triangleNormals);
  Buffer spheres = Buffer::withContents(context, scene.spheres);
  Buffer lights = Buffer::withContents(context, scene.lights);
  Buffer materials = Buffer::withContents(context, scene.materials);
  Buffer nodes = Buffer::withContents(context, scene.bvh.nodes);
  Buffer primRefs = Buffer::withContents(context, scene.bvh.primRefs);
  Buffer quadLights = Buffer::withContents(context, scene.quadLights);
  Buffer emitters = Buffer::withContents(context, scene.emitters);
  Buffer sums(context, std::size_t{width} * bandHeight * sizeof(gpu::vec4), true);
  Buffer states(context, std::size_t{width} * bandHeight * sizeof(gpu::GpuPathTracerState));
  Buffer counters(context, sizeof(gpu::GpuCounters), true);
  std::memset(counters.mapped(), 0, sizeof(gpu::GpuCounters));
  t.uploadSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  gpu::GpuRenderParams params{};
  params.width = width;
  params.height = height;
  params.maxDepth = scene.path.maxDepth;
  params.lightCount = static_cast<std::uint32_t>(scene.lights.size());
  const bool cpuDevice = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  params.stepBudget = options.stepBudget ? options.stepBudget
                                         : firstStepBudget(gpu::kDefaultStepBudget,
                                                           std::uint64_t{tilesInBand} * tile * tile, cpuDevice,
                                                           kPathFirstDispatchSteps);
  params.bandHeight = bandHeight;
  params.tilesX = tilesX;
  params.tileOrderStride = scatterStride(tilesInBand);
  params.primCount = static_cast<std::uint32_t>(scene.bvh.primRefs.size());
  const gpu::GpuBvhNode& root = scene.bvh.nodes[0];
  params.rootEntry = root.primCount > 0 ? gpu::kStackLeafBit | root.primCount << gpu::kStackCountShift |
                                              root.leftOrFirst
                                        : root.leftOrFirst;
  params.originX = static_cast<std::uint32_t>(region.x0);
  params.originY = static_cast<std::uint32_t>(region.y0);
  params.fullWidth = scene.width;
  params.fullHeight = scene.height;
  Buffer paramsBuffer(context, sizeof params);
  std::memcpy(paramsBuffer.mapped(), &params, sizeof params);
  StepPace pace;
  if (!options.stepBudget) pace = {&static_cast<gpu::GpuRenderParams*>(paramsBuffer.mapped())->stepBudget, gpu::kDefaultStepBudget};
  gpu::GpuPathParams path = scene.path;
  path.seed = options.seed;
  path.firstSample = options.firstSample;
  path.sampleCount = samples;
  path.jitter = renderSpp == 1 ? 0u : 1u;
  path.triangleCount = static_cast<std::uint32_t>(scene.triangles.size());
  path.sphereCount = static_cast<std::uint32_t>(scene.spheres.size());
  Buffer pathBuffer(context, sizeof path);
  std::memcpy(pathBuffer.mapped(), &path, sizeof path);

  // Every primitive of a small scene tested by every ray, when the BVH holds each exactly once.
  const std::size_t primitives = scene.triangles.size() + scene.spheres.size();
  const bool testAll =
      options.testAll && primitives <= gpu::kTestAllMaxPrims && scene.bvh.primRefs.size() == primitives;
  t.testedAll = testAll;
  const std::vector<std::uint32_t> spec = pathFeatures(scene, path.jitter, options.specialize, testAll, t.leftOut);
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const Buffer* sceneBuffers[] = {&triangles, &normals, &spheres, &lights, &materials, &nodes, &quadLights};
  bool texelsFit = primRefs.size() / 4 <= maxTexels;
  for (const Buffer* b : sceneBuffers) texelsFit = texelsFit && b->size() / 16 <= maxTexels;
  t.texelReads = options.reads == SceneReads::Texel || (options.reads == SceneReads::Auto && texelsFit);
  if (t.texelReads && !texelsFit)
    throw DeviceError("the scene is too large for texel-buffer reads on this device (limit " +
                      std::to_string(maxTexels) + " texels); use storage-buffer reads (--reads storage)");
  std::vector<VkDescriptorType> types(gpu::kPathBindingCount, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  if (t.texelReads) {
    std::fill(types.begin(), types.begin() + gpu::kBindingPixels, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    types[gpu::kBindingQuadLights] = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  }
  types[gpu::kBindingParams] = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  types[gpu::kBindingPathParams] = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  ComputePipeline pipeline(context, t.texelReads ? kPathtraceTexelSpirv : kPathtraceSpirv,
                           t.texelReads ? sizeof(kPathtraceTexelSpirv) : sizeof(kPathtraceSpirv), types, spec,
                           sizeof(gpu::GpuPathPush));
  const Buffer* bound[gpu::kPathBindingCount] = {};
  bound[gpu::kBindingTriangles] = &triangles;
  bound[gpu::kBindingTriangleNormals] = &normals;
  bound[gpu::kBindingSpheres] = &spheres;
  bound[gpu::kBindingLights] = &lights;
  bound[gpu::kBindingMaterials] = &materials;
  bound[gpu::kBindingBvhNodes] = &nodes;
  bound[gpu::kBindingPrimRefs] = &primRefs;
  bound[gpu::kBindingPixels] = &sums;
  bound[gpu::kBindingPathStates] = &states;
  bound[gpu::kBindingCounters] = &counters;
  bound[gpu::kBindingParams] = &paramsBuffer;
  bound[gpu::kBindingQuadLights] = &quadLights;
  bound[gpu::kBindingPathParams] = &pathBuffer;
  bound[gpu::kBindingEmitters] = &emitters;
  for (std::uint32_t b = 0; b < gpu::kPathBindingCount; ++b) {
    if (types[b] == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
      pipeline.bindUniform(b, *bound[b]);
    else if (types[b] == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
      pipeline.bind(b, *bound[b]);
    else if (b == gpu::kBindingPrimRefs)
      pipeline.bindTexels(b, *bound[b], VK_FORMAT_R32_UINT, 4);
    else
      pipeline.bindTexels(b, *bound[b], VK_FORMAT_R32G32B32A32_UINT, 16);
  }
  t.pipelineSeconds = secondsSince(t0);

  RadianceImage image(static_cast<int>(width), static_cast<int>(height));
  image.samples = samples;
  gpu::GpuPathPush push{};
  RayCounts counted;
  const std::uint64_t total = std::uint64_t{width} * height * samples;
  for (std::uint32_t y0 = 0; y0 < height; y0 += bandHeight) {
    push.bandY0 = y0;
    if (!dispatchBand(pipeline, &push, push.resume, y0, tilesInBand, counters, options.stop, t, counted, &pace))
      return image;

    t0 = std::chrono::steady_clock::now();
    const std::uint32_t rows = std::min(bandHeight, height - y0);
    const auto* sum = static_cast<const gpu::vec4*>(sums.mapped());
    const float scale = samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f;
    for (std::uint32_t y = 0; y < rows; ++y) {
      float* out = image.pixel(0, static_cast<int>(y0 + y));
      const gpu::vec4* in = sum + std::size_t{y} * width;
      for (std::uint32_t x = 0; x < width; ++x) {
        out[3 * x] = in[x].x * scale;
        out[3 * x + 1] = in[x].y * scale;
        out[3 * x + 2] = in[x].z * scale;
      }
    }
    t.readbackSeconds += secondsSince(t0);
    if (options.progress) options.progress(std::uint64_t{y0 + rows} * width * samples, total);
  }
  if (rays) {
    *rays = counted;
    rays->primary = std::uint64_t{width} * height * samples;
  }
  if (timings) *timings = t;
  return image;
}

}  // namespace vkrt
