// The Vulkan backend of the path integrators (doc/path-tracing.md: analyticdirect, direct,
// pathtracer): GpuScene -> RadianceImage through pathtrace.comp. Renders a range of samples
// per pixel and returns their mean in float, so that batches of one render can be averaged
// (weighted by their sample counts) into the same image as one render of all the samples.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "util/ray_counts.h"
#include "gpu/context.h"
#include "gpu/vulkan_renderer.h"
#include "image/crop.h"
#include "image/radiance_image.h"
#include "scene/flatten.h"

namespace vkrt {

struct VulkanPathOptions {
  SceneReads reads = SceneReads::Auto;    // Auto: texel buffers where the device's limits allow
  std::uint32_t seed = 0;                 // the generator's key (gpu_types.h)
  // This call renders samples [firstSample, firstSample + sampleCount) of every pixel; the
  // numbers each draws depend on its index only, not on the batch it comes in.
  std::uint32_t firstSample = 0;
  std::uint32_t sampleCount = 0;          // 0: the scene's spp
  // The whole render's samples per pixel, for the camera rule (gpu_types.h: a render of spp 1
  // samples the pixel centres, whatever sampleCount says); 0: the scene's spp.
  std::uint32_t renderSpp = 0;
  // Stratified samples over renderSpp (gpu_rng.h, rngStratify); false: independent ones.
  bool stratified = false;
  std::uint32_t stepBudget = 0;           // steps per invocation per dispatch; 0: paced by time
  // Pixels an invocation renders in turn (one of each tile of its workgroup's run); 0:
  // pathPixelsPerInvocation. The same image either way.
  std::uint32_t pixelsPerInvocation = 0;
  std::size_t maxStateBytes = 64u << 20;  // bounds a band's suspended-state buffer
  ShaderVariant variant = ShaderVariant::Specialized;   // the shader's: specialised to the scene, general, or Auto
  // Small scenes (testsEveryPrimitive): every ray tests each primitive instead of walking the
  // BVH (kSpecTestAll); false: always the BVH. The same image either way.
  bool testAll = true;
  // The BVH's interior nodes hold blocks of four children (scene/wide_bvh.h: GpuScene::bvh
  // collapsed, Bvh::wide), walked four boxes at a time; false: two (bench/README.md, "Tried
  // and not kept"). The same image but where two hits are equally near.
  bool wideBvh = false;
  std::function<void(std::uint64_t, std::uint64_t)> progress;   // (pixel samples done, total)
  std::function<bool()> stop;   // polled before each dispatch: true stops early (image incomplete)
  // Only these pixels of the scene's image, as an image of the crop's size: the full render's
  // pixels bit for bit (the same camera rays and random numbers).
  std::optional<PixelRect> crop;
};

// The pixels an invocation of the path shader renders in turn. On a CPU device a vector's
// lanes wait for the longest path among them: the pathtracer's paths end at any length, so
// a lane takes pixels until it has about kPathSamplesPerLane samples (at most
// kDefaultPixelsPerInvocation, 4 in a scene of more than kLargeScenePrimitives, where lanes
// that drift apart in the image lose the BVH's cache lines). The direct integrators' samples
// are of one length: one pixel a lane, as on a GPU, which has lanes to spare. (Measured on
// lavapipe: bench/README.md, "Path tracing on lavapipe".)
inline constexpr std::uint32_t kPathSamplesPerLane = 256;
inline constexpr std::size_t kLargeScenePrimitives = 10000;
std::uint32_t pathPixelsPerInvocation(bool cpuDevice, std::uint32_t integrator, std::uint32_t samples,
                                      std::size_t primitives);

class SceneUpload;

// A path-traced render on one device, in sample batches (renderProgressive): the scene's
// buffers are uploaded by the first batch and kept for the others. (On lavapipe a batch that
// uploaded the scene again, after an earlier batch had run, traced slower per sample than the
// first: bench/README.md, "`--time` against `--spp`, and the scene's buffers".) `scene` must
// outlive it.
class VulkanPathRender {
 public:
  VulkanPathRender(const Context& context, const GpuScene& scene);
  ~VulkanPathRender();
  VulkanPathRender(const VulkanPathRender&) = delete;
  VulkanPathRender& operator=(const VulkanPathRender&) = delete;
  // One batch: the samples of `options` (as renderVulkanPath).
  RadianceImage render(const VulkanPathOptions& options, RayCounts* rays, VulkanTimings* timings);
  // The scene's uploads so far: 1 after any number of batches.
  std::uint32_t uploads() const { return uploads_; }

 private:
  const Context& context_;
  const GpuScene& scene_;
  std::unique_ptr<SceneUpload> upload_;
  std::uint32_t uploads_ = 0;
};

// A render of one batch (VulkanPathRender of its own).
// RayCounts: primary = camera rays (pixels x samples), shadow = shadow rays, secondary =
// scattered rays, nonFinite = samples whose radiance was NaN or infinite (left out of the mean).
// Throws DeviceError (also for a scene beyond the backend's or the device's limits),
// OutOfMemory, InternalError.
RadianceImage renderVulkanPath(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                               RayCounts* rays, VulkanTimings* timings);

// Why the path shader cannot draw the light samples of a vertex ("" when it can): each
// vertex's random numbers lie within its stride of the generator's dimensions (gpu_types.h),
// two per quad-light sample where the integrator samples quad lights (direct, and pathtracer
// with next-event estimation), and three more per light sample where it samples `emitters`
// (pathtracer with next-event estimation).
std::string lightSlotsProblem(const gpu::GpuPathParams& path, bool emitters);

// Makes, in the context's PipelineCache, the pipeline that a batch of `options` will take,
// from `scene` before its BVH is built (flatten's arraysMade), as prepareVulkanPipeline does
// for the Whitted shader. `eachPrimitiveOnce`: the BVH will hold every primitive (none is
// one that can never be hit; it decides whether a small scene's rays test every primitive).
// Where the built BVH decides otherwise (a scene too large for texel reads), the batch makes
// its own. Throws as renderVulkanPath.
void prepareVulkanPathPipeline(const Context& context, const GpuScene& scene, const VulkanPathOptions& options,
                               bool eachPrimitiveOnce);

}  // namespace vkrt
