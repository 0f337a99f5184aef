// The band buffers of either Vulkan renderer.
#include "gpu/band_buffers.h"

#include <cstring>

namespace vkrt {

BandBuffers::BandBuffers(const Context& context, const BandLayout& layout, std::size_t stateBytes,
                         const gpu::GpuRenderParams& renderParams, bool paced)
    : width(layout.width),
      pixels(context, layout.bandPixels() * sizeof(gpu::vec4), true),
      states(context, stateBytes),
      counters(context, sizeof(gpu::GpuCounters), true),
      params(context, sizeof renderParams) {
  std::memset(counters.mapped(), 0, sizeof(gpu::GpuCounters));
  std::memcpy(params.mapped(), &renderParams, sizeof renderParams);
  if (paced) pace = {&static_cast<gpu::GpuRenderParams*>(params.mapped())->stepBudget, gpu::kDefaultStepBudget};
}

void BandBuffers::bind(ShaderBindings& bindings) const {
  bindings.set(gpu::kBindingPixels, pixels, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  bindings.set(gpu::kBindingPathStates, states, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  bindings.set(gpu::kBindingCounters, counters, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  bindings.set(gpu::kBindingParams, params, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
}

void BandBuffers::readRows(std::uint32_t rows, float scale, RadianceImage& image, int y0) const {
  const auto* band = static_cast<const gpu::vec4*>(pixels.mapped());
  for (std::uint32_t y = 0; y < rows; ++y) {
    float* out = image.pixel(0, y0 + static_cast<int>(y));
    const gpu::vec4* in = band + std::size_t{y} * width;
    for (std::uint32_t x = 0; x < width; ++x) {
      out[3 * x] = in[x].x * scale;
      out[3 * x + 1] = in[x].y * scale;
      out[3 * x + 2] = in[x].z * scale;
    }
  }
}

}  // namespace vkrt
