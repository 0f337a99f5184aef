// The band buffers of either Vulkan renderer.
#include "gpu/band_buffers.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "timing.h"

namespace vkrt {

BandBuffers::BandBuffers(const Context& context, const BandLayout& layout, std::size_t stateBytes,
                         gpu::GpuRenderParams renderParams, std::uint32_t stepBudget, double firstDispatchSteps)
    : width(layout.width),
      pixels(context, layout.bandPixels() * sizeof(gpu::vec4), true),
      states(context, stateBytes),
      counters(context, sizeof(gpu::GpuCounters), true),
      params(context, sizeof renderParams) {
  std::memset(counters.mapped(), 0, sizeof(gpu::GpuCounters));
  const bool cpuDevice = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  renderParams.stepBudget = stepBudget ? stepBudget
                                       : firstStepBudget(gpu::kDefaultStepBudget, layout.invocations(), cpuDevice,
                                                         firstDispatchSteps);
  std::memcpy(params.mapped(), &renderParams, sizeof renderParams);
  if (!stepBudget) pace = {&static_cast<gpu::GpuRenderParams*>(params.mapped())->stepBudget, gpu::kDefaultStepBudget};
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

bool BandBuffers::run(ComputePipeline& pipeline, const void* push, std::uint32_t& bandY0, std::uint32_t& resume,
                      const BandLayout& layout, std::uint32_t samples, const BandHooks& hooks, VulkanTimings& timings,
                      RayCounts& rays) {
  const std::uint64_t total = std::uint64_t{layout.width} * layout.height * samples;
  for (std::uint32_t y0 = 0; y0 < layout.height; y0 += layout.bandHeight) {
    bandY0 = y0;
    if (!dispatchBand(pipeline, push, resume, y0, layout.groups, counters, hooks.stop, timings, rays, &pace))
      return false;
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint32_t rows = std::min(layout.bandHeight, layout.height - y0);
    hooks.read(y0, rows);
    timings.readbackSeconds += secondsSince(t0);
    if (hooks.after) hooks.after(y0, rows);
    if (hooks.progress) hooks.progress(std::uint64_t{y0 + rows} * layout.width * samples, total);
  }
  rays.primary = total;
  return true;
}

}  // namespace vkrt
