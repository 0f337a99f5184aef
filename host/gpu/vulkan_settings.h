// The Vulkan backend's choices and its timing report, without the Vulkan API: what option
// handling and the render report need (render/render.h) of gpu/vulkan_renderer.h.
#pragma once

#include <cstdint>
#include <string>

namespace vkrt {

// How the shader reads the scene: storage buffers, or storage texel buffers read with imageLoad
// (faster on lavapipe; limited to maxTexelBufferElements texels per buffer and
// maxPerStageDescriptorStorageImages buffers per shader).
enum class SceneReads { Auto, Storage, Texel };

enum class Cutoff { Auto, On, Off };

// Which variant of the shader a render compiles (gpu/shader_variant.h): the one specialised to
// the scene's features, the general one (every feature in; compiled once per machine), or
// Auto: the specialised one where it pays for its compile or, on a CPU device, is compiled
// already (autoTakesSpecialised).
enum class ShaderVariant { Specialized, General, Auto };

struct VulkanTimings {
  double uploadSeconds = 0, pipelineSeconds = 0, firstDispatchSeconds = 0, dispatchSeconds = 0,
         readbackSeconds = 0;
  std::uint32_t bands = 0, dispatches = 0;
  std::uint64_t suspensions = 0;   // invocations (Whitted) or pixels (path tracing) that ran out of steps, over the dispatches
  bool texelReads = false;         // which shader variant ran
  bool testedAll = false;          // the shader tested every primitive (no BVH walk)
  std::string leftOut;             // the features compiled out, e.g. "spheres, specular (maxdepth 0)"
  bool general = false;            // the general variant ran (Variant)
  double estimatedRays = 0;        // what ShaderVariant::Auto went by
};

// A render's timings over its sample batches: `batch`'s added to `total`. The first batch's
// first dispatch stays apart (it holds the driver's JIT); a later batch's counts as dispatch
// time. The variant (texelReads, testedAll, leftOut) is every batch's.
inline void addBatchTimings(VulkanTimings& total, const VulkanTimings& batch, bool firstBatch) {
  total.uploadSeconds += batch.uploadSeconds;
  total.pipelineSeconds += batch.pipelineSeconds;
  if (firstBatch)
    total.firstDispatchSeconds = batch.firstDispatchSeconds;
  else
    total.dispatchSeconds += batch.firstDispatchSeconds;
  total.dispatchSeconds += batch.dispatchSeconds;
  total.readbackSeconds += batch.readbackSeconds;
  total.bands += batch.bands;
  total.dispatches += batch.dispatches;
  total.suspensions += batch.suspensions;
  total.texelReads = batch.texelReads;
  total.testedAll = batch.testedAll;
  total.leftOut = batch.leftOut;
  total.general = batch.general;
  total.estimatedRays = batch.estimatedRays;
}

}  // namespace vkrt
