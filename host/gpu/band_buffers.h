// The buffers a Vulkan render computes its bands in, beside the scene's: the band's pixels
// (kBindingPixels), its suspended state, the counters and the GpuRenderParams; and reading a
// band's pixels back into an image.
#pragma once

#include <cstddef>
#include <cstdint>

#include "gpu/band_dispatch.h"
#include "gpu/band_layout.h"
#include "gpu/buffer.h"
#include "gpu/scene_upload.h"
#include "image/radiance_image.h"

namespace vkrt {

struct BandBuffers {
  // `stateBytes` for the suspended state; `params` copied into a uniform buffer, its step
  // budget paced by time when `paced` (StepPace; an explicit budget is not).
  BandBuffers(const Context& context, const BandLayout& layout, std::size_t stateBytes,
              const gpu::GpuRenderParams& params, bool paced);
  // Sets kBindingPixels, kBindingPathStates, kBindingCounters and kBindingParams.
  void bind(ShaderBindings& bindings) const;
  // The first `rows` rows of the band's pixels (rgb of a vec4 each, times `scale`) into
  // `image` from its row `y0`.
  void readRows(std::uint32_t rows, float scale, RadianceImage& image, int y0) const;

  std::uint32_t width;
  Buffer pixels, states, counters, params;
  StepPace pace;
};

}  // namespace vkrt
