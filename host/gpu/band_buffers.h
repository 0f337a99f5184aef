// The buffers a Vulkan render computes its bands in, beside the scene's: the band's pixels
// (kBindingPixels), its suspended state, the counters and the GpuRenderParams; and reading a
// band's pixels back into an image.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/buffer.h"
#include "gpu/scene_upload.h"
#include "image/radiance_image.h"

namespace vkrt {

// What a render does around its bands (BandBuffers::run).
struct BandHooks {
  std::function<bool()> stop;   // polled before each dispatch: true stops early
  // (pixel samples done, total), after each dispatch: the samples (or Whitted pixels) it
  // finished, counted by the shader.
  std::function<void(std::uint64_t, std::uint64_t)> progress;
  // Reads the finished band of `rows` rows from image row `y0` out of the pixel buffer
  // (timed as readback); then `after` (may be empty; not timed) hands them on.
  std::function<void(std::uint32_t y0, std::uint32_t rows)> read, after;
};

struct BandBuffers {
  // `stateBytes` for the suspended state; `params` copied into a storage buffer with the step
  // budget `stepBudget`, or with 0 one paced by time (StepPace) from the first dispatch's
  // `firstDispatchSteps` (kWhittedFirstDispatchSteps or kPathFirstDispatchSteps). With
  // `timedBands` (pathtrace.comp, one tile a workgroup) and a paced budget, bands are sized by
  // time too (timedBandRows), up to the layout's rows; otherwise every band has the layout's.
  BandBuffers(const Context& context, const BandLayout& layout, std::size_t stateBytes, gpu::GpuRenderParams params,
              std::uint32_t stepBudget, double firstDispatchSteps, bool timedBands = false);
  // Sets kBindingPixels, kBindingPathStates, kBindingCounters and kBindingParams.
  void bind(ShaderBindings& bindings) const;
  // The first `rows` rows of the band's pixels (rgb of a vec4 each, times `scale`) into
  // `image` from its row `y0`.
  void readRows(std::uint32_t rows, float scale, RadianceImage& image, int y0) const;
  // Runs the bands of `layout` from the top, each dispatched (dispatchBand; `push` the push
  // constants, with their `bandY0` and `resume` fields) until finished and then read back
  // (`hooks`); `samples` per pixel. Counts the rays into `rays`, the camera rays (pixels x
  // samples) once every band is done. Returns false when `hooks.stop` ended it early.
  bool run(ComputePipeline& pipeline, const void* push, std::uint32_t& bandY0, std::uint32_t& resume,
           const BandLayout& layout, std::uint32_t samples, const BandHooks& hooks, VulkanTimings& timings,
           RayCounts& rays);

  std::uint32_t width;
  Buffer pixels, states, counters, params;
  StepPace pace;
  std::uint32_t firstBandRows = 0;   // timed bands: the first band's rows; 0: the layout's bands
};

}  // namespace vkrt
