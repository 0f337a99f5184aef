// The band driver of every GPU rendering technique (the Whitted model, the path integrators):
// what a technique describes of one batch (its shader, its state, its parameters, its push
// constants, how its pixels read back), and the one function that runs it: the band buffers,
// the bindings, the pipeline, the bands dispatched until no pixel is left suspended
// (BandBuffers::run), the readback, and what --stats says of the shader. A technique's own
// file (vulkan_renderer.cpp, vulkan_path_renderer.cpp) chooses and fills these; its shader's
// main() is shaders/driver.glsl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/band_layout.h"
#include "gpu/context.h"
#include "gpu/scene_upload.h"
#include "gpu/vulkan_settings.h"
#include "image/radiance_image.h"
#include "image/row_sink.h"
#include "util/ray_counts.h"

namespace vkrt {

// The SPIR-V of a technique's shader, shaders/NAME.comp, built with storage reads and with
// texel reads (VKRT_TEXEL_READS); CMakeLists.txt builds every one.
struct TechniqueSpirv {
  const char* name;
  const std::uint32_t* words;
  std::size_t bytes;
  const std::uint32_t* texelWords;
  std::size_t texelBytes;
};
// Throws InternalError when there is no shaders/NAME.comp.
const TechniqueSpirv& techniqueSpirv(std::string_view name);

// A technique's compute shader as chosen for a batch: the module (texel or storage reads, or
// another build of it), the variant's specialization constants, and what --stats says of them.
struct TechniqueShader {
  const std::uint32_t* words = nullptr;
  std::size_t bytes = 0;
  std::vector<std::uint32_t> spec;
  bool testAll = false;      // rays test every primitive (testsEveryPrimitive), specialised or general
  bool texelReads = false, general = false;
  std::uint64_t specializedKey = 0;   // the specialised variant's, general or not
  double estimatedRays = 0;           // what ShaderVariant::Auto went by
  std::string leftOut;                // the features compiled out
};

// A technique's push constants: its own struct, whose bandY0 and resume the driver sets.
struct TechniquePush {
  void* data = nullptr;
  std::uint32_t bytes = 0;
  std::uint32_t* bandY0 = nullptr;
  std::uint32_t* resume = nullptr;
};
template <class Push>
TechniquePush techniquePush(Push& push) {
  return {&push, static_cast<std::uint32_t>(sizeof push), &push.bandY0, &push.resume};
}

// One batch of a technique, besides its shader and the scene's upload.
struct TechniqueBatch {
  SceneArrays arrays = SceneArrays::Whitted;   // the scene's arrays its shader binds
  BandLayout layout;
  std::size_t stateBytes = 0;           // the suspended state of one invocation (gpu_*.h)
  gpu::GpuRenderParams params{};        // renderParams; the step budget is the driver's
  std::uint32_t stepBudget = 0;         // steps per invocation per dispatch; 0: paced by time
  double firstDispatchSteps = 0;        // StepPace: kWhittedFirstDispatchSteps or kPathFirstDispatchSteps
  bool timedBands = false;              // bands sized by time (BandBuffers)
  std::uint32_t samples = 1;            // traced per pixel: the progress bar's and the camera rays' count
  std::uint32_t imageSamples = 1;       // the image's RadianceImage::samples (the mean of how many)
  float readScale = 1.0f;               // the image is a band pixel's rgb times this
  TechniquePush push;
  std::function<void(ShaderBindings&)> bindOwn;   // the technique's own buffers (may be empty)
  std::function<bool()> stop;           // polled before each dispatch: true stops early
  std::function<void(std::uint64_t, std::uint64_t)> progress;   // (pixel samples done, total)
  // When set, each band is handed here as it is read back and not kept: the image returned
  // has no pixels (image/row_sink.h; rows relative to the region's top).
  RowSink rows;
};

// Renders `batch` with `shader` over the scene's `upload`. `t` comes with the caller's upload
// seconds and gets the rest; `rays` and `timings` (may be null) receive the counts and `t` once
// the render is whole. Returns the image, incomplete when `batch.stop` ended it (rays and
// timings are then left as they were). Throws as renderVulkan.
RadianceImage renderTechniqueBands(const Context& context, const SceneUpload& upload, const TechniqueShader& shader,
                                   const TechniqueBatch& batch, RayCounts* rays, VulkanTimings* timings,
                                   VulkanTimings t);

// Makes, in the context's PipelineCache, the pipeline that a batch of `shader` will take (a
// pipeline made ahead, while the BVH builds).
void prepareTechnique(const Context& context, const TechniqueShader& shader, SceneArrays arrays,
                      std::uint32_t pushBytes);

}  // namespace vkrt
