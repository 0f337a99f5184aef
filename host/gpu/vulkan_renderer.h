// The Vulkan backend: GpuScene -> RadianceImage through raytrace.comp. The image is traced in bands
// of rows (bounded memory, a moving progress bar); each band is dispatched again until no
// pixel is left suspended (the loop budget of llvmpipe, see gpu_types.h).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "util/ray_counts.h"
#include "gpu/context.h"
#include "gpu/vulkan_settings.h"
#include "image/crop.h"
#include "image/radiance_image.h"
#include "image/row_sink.h"
#include "scene/flatten.h"

namespace vkrt {

struct VulkanOptions {
  // The shader: "raytrace" (shaders/raytrace.comp, the Whitted model), or a view's
  // (render/techniques.cpp) that keeps this host's state and parameters (GpuWhittedState,
  // GpuPushConstants) and walks its pixels the same way (shaders/whitted_host.glsl).
  std::string_view shader = "raytrace";
  SceneReads reads = SceneReads::Auto;    // Auto: texel buffers where the device's limits allow
  std::uint32_t stepBudget = 0;           // steps per invocation per dispatch; 0: kDefaultStepBudget
  std::size_t maxStateBytes = 64u << 20;  // bounds a band's suspended-state buffer
  // The Whitted shader's invocations share out a band's pixels (raytrace.comp): a workgroup
  // takes a run of this many 8x8 tiles, an invocation one pixel of each; 0: on a CPU device
  // (lavapipe) kDefaultPixelsPerInvocation, on a GPU 1 (one pixel per invocation).
  std::uint32_t pixelsPerInvocation = 0;
  ShaderVariant variant = ShaderVariant::Specialized;   // the shader's: specialised to the scene, general, or Auto
  // The exactness cut-off of the mirror loop (gpu_types.h): Auto compiles it in only when it
  // can stop a path at least two bounces before maxdepth (on lavapipe its test costs more trace
  // time than it saves on scenes with bright lights and shallow mirrors: bench/README.md, "The
  // Whitted shader on lavapipe").
  Cutoff cutoff = Cutoff::Auto;
  // Small scenes (testsEveryPrimitive): every ray tests each primitive instead of walking the
  // BVH (kSpecTestAll); false: always the BVH. The same image either way.
  bool testAll = true;
  // The BVH's interior nodes hold blocks of four children (scene/wide_bvh.h: GpuScene::bvh
  // collapsed, Bvh::wide), walked four boxes at a time; false: two (bench/README.md, "Tried
  // and not kept"). The same image but where two hits are equally near.
  bool wideBvh = false;
  std::function<void(std::uint64_t, std::uint64_t)> progress;   // (pixels done, pixels total)
  std::function<bool()> stop;   // polled before each dispatch: true stops early (image incomplete)
  // Only these pixels of the scene's image (inside it), as an image of the crop's size; the
  // camera rays are the full image's (GpuRenderParams).
  std::optional<PixelRect> crop;
  // The samples to render, as CpuOptions (cpu/reference.h): [firstSample, firstSample +
  // sampleCount) with `seed`; the image is their mean, with RadianceImage::samples =
  // sampleCount. The Whitted model traces one (it is deterministic) and ignores the seed.
  std::uint32_t seed = 0;
  std::uint64_t firstSample = 0;
  std::uint32_t sampleCount = 1;
  // When set, each band is handed to `rows` as it is read back (image/row_sink.h) and not
  // kept: the image returned has no pixels, and memory is the band buffers'. Rows are
  // relative to the region (the crop's top is 0).
  RowSink rows;
};

// Throws DeviceError (also for a scene beyond the backend's or the device's limits),
// OutOfMemory, InternalError.
// The Whitted model (raytrace.comp); the path integrators plug in beside it, for
// scene.integrator != kIntegratorRaytracer.
RadianceImage renderVulkan(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           RayCounts* rays, VulkanTimings* timings);

// Makes, in the context's PipelineCache, the pipeline that renderVulkan(context, scene,
// options) will take, from `scene` before its BVH is built (flatten's arraysMade): lavapipe's
// pipeline creation (bench/README.md, "Fixed cost of the Vulkan backend") then overlaps the
// BVH build.
// `eachPrimitiveOnce`: whether the BVH will hold every primitive exactly once (the caller asks
// shapes::anyNeverHit of scenes small enough to test every primitive). Where the built BVH
// decides otherwise (a scene too large for texel reads), the render makes its own. Throws as
// renderVulkan.
void prepareVulkanPipeline(const Context& context, const GpuScene& scene, const VulkanOptions& options,
                           bool eachPrimitiveOnce);

}  // namespace vkrt
