// The path integrators' host side: upload, pipeline, band-by-band dispatch until no pixel is
// left suspended, readback of the float sums as their mean.
#include "gpu/vulkan_path_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>
#include <string>

#include "util/counted.h"
#include "util/errors.h"
#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/buffer.h"
#include "gpu/device_error.h"
#include "gpu/scene_features.h"
#include "gpu/scene_upload.h"
#include "gpu/shader_variant.h"
#include "gpu/technique_bands.h"
#include "pathtrace_quad.comp.h"         // kPathtraceQuadSpirv: VKRT_QUAD_LIGHTS_ONLY
#include "pathtrace_quad_texel.comp.h"   // kPathtraceQuadTexelSpirv: both
#include "util/timing.h"

namespace vkrt {
namespace {

// The features pathtrace.comp is specialised to (all on when not specializing), and what was
// left out, for --stats; the integrator settings (kPathSpecFromParams when not specializing,
// but for the sampler); and whether rays test every primitive instead of walking the BVH
// (either way), and the BVH's width (either way).
std::vector<std::uint32_t> pathFeatures(const GpuScene& scene, const gpu::GpuPathParams& path, bool specialize,
                                        bool testAll, bool wideBvh, std::string& leftOut) {
  std::vector<std::uint32_t> spec(gpu::kPathSpecCount, 1u);   // bools as 0/1 (32-bit spec constants)
  for (std::uint32_t i = gpu::kPathSpecIntegrator; i <= gpu::kPathSpecJitter; ++i) spec[i] = gpu::kPathSpecFromParams;
  // The sampler is specialised in the general variant too: read from the parameters, the strata's
  // code ran for every number drawn in renders of independent samples as well (lavapipe runs
  // both sides of an `if`; what it cost: bench/README.md, "Latest figures: first render, shader
  // variants, responsiveness"). A machine
  // whose renders use both samplers compiles a general variant for each.
  spec[gpu::kPathSpecSampler] = path.strataSide > 0 ? 1u : 0u;
  spec[gpu::kSpecTestAll] = testAll;
  spec[gpu::kSpecWideBvh] = wideBvh;
  if (!specialize) return spec;
  bool ggx = false;
  for (const gpu::GpuMaterial& m : scene.materials) ggx = ggx || m.ambient.w == gpu::kBrdfGgx;
  setSharedFeatures(scene, spec);
  spec[gpu::kPathSpecHasQuadLights] = !scene.quadLights.empty();
  spec[gpu::kPathSpecHasGgx] = ggx;
  spec[gpu::kPathSpecHasEmitters] = !scene.emitters.empty();
  // The integrator settings (a shader per combination; each is compiled once and cached).
  spec[gpu::kPathSpecIntegrator] = scene.path.integrator;
  spec[gpu::kPathSpecNextEvent] = scene.path.nextEvent;
  spec[gpu::kPathSpecSampling] = scene.path.sampling;
  spec[gpu::kPathSpecRussianRoulette] = scene.path.russianRoulette;
  spec[gpu::kPathSpecStratified] = scene.path.lightStrata > 0 ? 1u : 0u;
  spec[gpu::kPathSpecJitter] = path.jitter;
  leftOut = leftOutNames(spec, {{gpu::kPathSpecHasQuadLights, "quad lights"},
                                {gpu::kPathSpecHasGgx, "ggx"},
                                {gpu::kPathSpecHasEmitters, "emissive surfaces"}});
  return spec;
}

// The embedded path shader: texel or storage reads, whole or built for quad lights alone
// (VKRT_QUAD_LIGHTS_ONLY: without the code of point and directional lights, emitters and
// analyticdirect).
struct PathModule {
  const std::uint32_t* words;
  std::size_t bytes;
};
PathModule pathModule(bool texelReads, bool quadLightsOnly) {
  if (quadLightsOnly)
    return texelReads ? PathModule{kPathtraceQuadTexelSpirv, sizeof kPathtraceQuadTexelSpirv}
                      : PathModule{kPathtraceQuadSpirv, sizeof kPathtraceQuadSpirv};
  const TechniqueSpirv& whole = techniqueSpirv("pathtrace");
  return texelReads ? PathModule{whole.texelWords, whole.texelBytes} : PathModule{whole.words, whole.bytes};
}

// Throws DeviceError for lightSlotsProblem (the render's caller says where in the scene first).
void checkLightSlots(const GpuScene& scene) {
  if (std::string problem = lightSlotsProblem(scene.path, !scene.emitters.empty()); !problem.empty())
    throw DeviceError(problem);
}

}  // namespace

// Two per quad-light sample, and with emitters two more and a pick per light sample.
std::string lightSlotsProblem(const gpu::GpuPathParams& path, bool emitters) {
  const bool nextEvent = path.integrator == gpu::kIntegratorPathTracer && path.nextEvent != gpu::kNextEventOff;
  const bool quads = nextEvent || path.integrator == gpu::kIntegratorDirect;
  emitters = emitters && nextEvent;
  const std::uint64_t n = path.lightSamples;
  const std::uint64_t lightSlots = (quads ? std::uint64_t{path.quadLightCount} * n * 2 : 0) + (emitters ? n * 3 : 0);
  if (gpu::kRngSlotLightBase + lightSlots <= gpu::kRngBounceStride) return "";
  std::string parts;
  if (quads) parts = counted(path.quadLightCount, "quad light", "quad lights") + " x " + std::to_string(n) + " lightsamples x 2";
  if (emitters) parts += std::string(quads ? ", and " : "") + std::to_string(n) + " lightsamples x 3 for the emitting surfaces";
  return "the Vulkan backend draws at most " + std::to_string(gpu::kRngBounceStride - gpu::kRngSlotLightBase) +
         " random numbers for the light samples of a path vertex; this scene needs " + std::to_string(lightSlots) +
         " (" + parts + "): use fewer quad lights or lightsamples, or --backend cpu";
}

namespace {

// The shader a path render runs, decided before its buffers are made, and its parameters.
struct PathShader {
  TechniqueShader shader;
  gpu::GpuPathParams path{};   // the scene's, with the batch's seed, samples and sampler
};

// `texelsFit`: SceneUpload::texelsFit; `eachPrimitiveOnce`: the BVH holds every primitive
// exactly once. Before the BVH is built (a pipeline made ahead): texelsFitBeforeBvh, and
// whether the scene has no primitive that can never be hit (prepareVulkanPathPipeline's
// caller asks shapes::anyNeverHit).
PathShader pathShader(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                      const BandLayout& layout, std::uint32_t samples, bool texelsFit, bool eachPrimitiveOnce) {
  PathShader p;
  TechniqueShader& s = p.shader;
  const bool cpuDevice = context.isCpuDevice();
  const std::uint32_t renderSpp = options.renderSpp ? options.renderSpp : scene.spp;
  gpu::GpuPathParams& path = p.path;
  path = scene.path;
  path.seed = options.seed;
  path.firstSample = options.firstSample;
  path.sampleCount = samples;
  path.jitter = renderSpp == 1 ? 0u : 1u;
  path.strataSide = options.stratified ? gpu::rngStrataSide(renderSpp) : 0u;
  s.testAll = testsEveryPrimitive(scene, options.testAll, eachPrimitiveOnce);
  s.texelReads = chooseTexelReads(options.reads, SceneArrays::Path, texelsFit, context.properties().limits);
  // The rays, about (what ShaderVariant::Auto goes by): per sample a camera ray; direct: a
  // shadow ray per light sample of each quad light; pathtracer: per vertex (4 where only
  // Russian roulette ends the path) a scattered ray and, with next-event estimation, a shadow
  // ray per light sample of each light.
  const double lightRays = static_cast<double>(scene.path.lightSamples) * (scene.path.quadLightCount + 1.0);
  double perSample = 1.0;
  if (scene.path.integrator == gpu::kIntegratorDirect)
    perSample += lightRays;
  else if (scene.path.integrator == gpu::kIntegratorPathTracer)
    perSample += (scene.path.maxDepth == gpu::kUnlimitedDepth ? 4.0 : std::min(scene.path.maxDepth, 8u)) *
                 (1.0 + (scene.path.nextEvent != gpu::kNextEventOff ? lightRays : 0.0));
  s.estimatedRays = static_cast<double>(layout.width) * layout.height * samples * perSample;
  std::string leftOut;
  const std::vector<std::uint32_t> specialized = pathFeatures(scene, path, true, s.testAll, options.wideBvh, leftOut);
  // A scene whose lights are all quad lights, rendered by direct or pathtracer, takes the module
  // without the code of the other lights and of analyticdirect, specialised or general (whose
  // pipeline lavapipe then creates faster: bench/README.md, "Path tracing on lavapipe").
  const bool quadLightsOnly = !specialized[gpu::kSpecHasPointLights] && !specialized[gpu::kSpecHasDirectionalLights] &&
                              !specialized[gpu::kPathSpecHasEmitters] &&
                              specialized[gpu::kPathSpecIntegrator] != gpu::kIntegratorAnalyticDirect;
  const PathModule module = pathModule(s.texelReads, quadLightsOnly);
  s.words = module.words;
  s.bytes = module.bytes;
  s.specializedKey = variantKey(context.properties(), s.words, s.bytes, specialized);
  s.general = options.variant == ShaderVariant::General ||
              (options.variant == ShaderVariant::Auto &&
               !autoTakesSpecialised(cpuDevice, s.estimatedRays, true, s.specializedKey));
  // The general variant: every feature on, in the same module.
  s.spec = s.general ? pathFeatures(scene, path, false, s.testAll, options.wideBvh, s.leftOut) : specialized;
  if (!s.general) s.leftOut = leftOut;
  return p;
}

// The band layout of a path render of `samples` samples: one GpuPathTracerState per
// invocation, shared by its perInvocation pixels; the workgroups of a band each take a run of
// perInvocation adjacent 8x8 tiles.
BandLayout pathLayout(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                      std::uint32_t samples) {
  const bool cpuDevice = context.isCpuDevice();
  const std::uint32_t perInvocation =
      options.pixelsPerInvocation
          ? options.pixelsPerInvocation
          : pathPixelsPerInvocation(cpuDevice, scene.path.integrator, samples, primitiveCount(scene));
  return bandLayout(renderRegion(scene, options.crop), sizeof(gpu::GpuPathTracerState), options.maxStateBytes,
                    perInvocation);
}

}  // namespace

std::uint32_t pathPixelsPerInvocation(bool cpuDevice, std::uint32_t integrator, std::uint32_t samples,
                                      std::size_t primitives) {
  if (!cpuDevice || integrator != gpu::kIntegratorPathTracer) return 1;
  const std::uint32_t most = primitives > kLargeScenePrimitives ? 4u : gpu::kDefaultPixelsPerInvocation;
  return std::clamp((kPathSamplesPerLane + samples - 1) / std::max(samples, 1u), 1u, most);
}

void prepareVulkanPathPipeline(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                               bool eachPrimitiveOnce) {
  const std::uint32_t samples = options.sampleCount ? options.sampleCount : scene.spp;
  checkLightSlots(scene);
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const PathShader p = pathShader(context, scene, options, pathLayout(context, scene, options, samples), samples,
                                  texelsFitBeforeBvh(scene, SceneArrays::Path, maxTexels, options.wideBvh), eachPrimitiveOnce);
  prepareTechnique(context, p.shader, SceneArrays::Path, sizeof(gpu::GpuPathPush));
}

VulkanPathRender::VulkanPathRender(const Context& context, const GpuScene& scene) : context_(context), scene_(scene) {}
VulkanPathRender::~VulkanPathRender() = default;

RadianceImage renderVulkanPath(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                               RayCounts* rays, VulkanTimings* timings) {
  return VulkanPathRender(context, scene).render(options, rays, timings);
}

RadianceImage VulkanPathRender::render(const VulkanPathOptions& options, RayCounts* rays, VulkanTimings* timings) {
  const Context& context = context_;
  const GpuScene& scene = scene_;
  VulkanTimings t;
  if (scene.path.integrator == gpu::kIntegratorRaytracer)
    throw InternalError("renderVulkanPath called for the raytracer integrator (renderVulkan renders it)");
  const std::uint32_t samples = options.sampleCount ? options.sampleCount : scene.spp;
  TechniqueBatch batch;
  batch.layout = pathLayout(context, scene, options, samples);
  checkShaderLimits(scene, options.wideBvh);
  checkLightSlots(scene);

  auto t0 = std::chrono::steady_clock::now();
  if (!upload_) {
    upload_ = std::make_unique<SceneUpload>(context, scene, SceneArrays::Path);
    ++uploads_;
  }
  t.uploadSeconds = secondsSince(t0);
  t0 = std::chrono::steady_clock::now();
  const std::size_t maxTexels = context.properties().limits.maxTexelBufferElements;
  const PathShader p = pathShader(context, scene, options, batch.layout, samples, upload_->texelsFit(maxTexels),
                                  bvhHoldsEachPrimitiveOnce(scene));
  Buffer pathBuffer(context, sizeof p.path);
  std::memcpy(pathBuffer.mapped(), &p.path, sizeof p.path);
  t.pipelineSeconds = secondsSince(t0);

  batch.arrays = SceneArrays::Path;
  batch.stateBytes = sizeof(gpu::GpuPathTracerState);
  batch.params = renderParams(scene, batch.layout, scene.path.maxDepth);
  batch.stepBudget = options.stepBudget;
  batch.firstDispatchSteps = kPathFirstDispatchSteps;
  batch.timedBands = true;
  batch.samples = samples;
  batch.imageSamples = samples;
  batch.readScale = samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f;   // the sums' mean
  gpu::GpuPathPush push{};
  batch.push = techniquePush(push);
  batch.bindOwn = [&](ShaderBindings& bindings) { bindings.set(gpu::kBindingPathParams, pathBuffer); };
  batch.stop = options.stop;
  batch.progress = options.progress;
  return renderTechniqueBands(context, *upload_, p.shader, batch, rays, timings, t);
}

}  // namespace vkrt
