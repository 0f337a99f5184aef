// The band buffers of either Vulkan renderer.
#include "gpu/band_buffers.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "gpu/tile_order.h"
#include "util/timing.h"

namespace vkrt {

BandBuffers::BandBuffers(const Context& context, const BandLayout& layout, std::size_t stateBytes,
                         gpu::GpuRenderParams renderParams, std::uint32_t stepBudget, double firstDispatchSteps,
                         bool timedBands)
    : width(layout.width),
      pixels(context, layout.bandPixels() * sizeof(gpu::vec4), true),
      states(context, stateBytes),
      counters(context, sizeof(gpu::GpuCounters), true),
      params(context, sizeof renderParams) {
  std::memset(counters.mapped(), 0, sizeof(gpu::GpuCounters));
  const bool cpuDevice = context.isCpuDevice();
  if (timedBands && !stepBudget)
    firstBandRows = firstTimedBandRows(gpu::kDefaultStepBudget / layout.tilesPerGroup, layout.width,
                                       layout.bandHeight, cpuDevice, firstDispatchSteps);
  const std::uint64_t firstInvocations = firstBandRows ? std::uint64_t{layout.groupsFor(firstBandRows)} *
                                                            gpu::kWorkgroupSize * gpu::kWorkgroupSize
                                                      : layout.invocations();
  renderParams.stepBudget = stepBudget ? stepBudget
                                       : firstStepBudget(gpu::kDefaultStepBudget, firstInvocations, cpuDevice,
                                                         firstDispatchSteps);
  std::memcpy(params.mapped(), &renderParams, sizeof renderParams);
  if (!stepBudget) pace = {&static_cast<gpu::GpuRenderParams*>(params.mapped())->stepBudget, gpu::kDefaultStepBudget};
}

void BandBuffers::bind(ShaderBindings& bindings) const {
  bindings.set(gpu::kBindingPixels, pixels);
  bindings.set(gpu::kBindingPathStates, states);
  bindings.set(gpu::kBindingCounters, counters);
  bindings.set(gpu::kBindingParams, params);
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
  auto* shared = static_cast<gpu::GpuRenderParams*>(params.mapped());
  std::uint64_t finished = 0, bandSteps = 0;
  double bandSeconds = 0;
  const std::function<void(const DispatchDone&)> done = [&](const DispatchDone& d) {
    finished += d.finished;
    bandSteps += d.steps;
    bandSeconds += d.seconds;
    if (hooks.progress) hooks.progress(std::min(finished, total), total);
  };
  std::uint32_t bandRows = firstBandRows ? firstBandRows : layout.bandHeight;
  for (std::uint32_t y0 = 0, next = bandRows; y0 < layout.height; y0 += bandRows, bandRows = next) {
    std::uint32_t groups = layout.groups;
    if (firstBandRows) {   // a band of its own height: its tiles, and their scattered order
      groups = layout.groupsFor(bandRows);
      shared->bandHeight = bandRows;
      shared->tileOrderStride = scatterStride(groups);
    }
    bandY0 = y0;
    bandSteps = 0;
    bandSeconds = 0;
    if (!dispatchBand(pipeline, push, resume, y0, groups, counters, hooks.stop, timings, rays, &pace, done))
      return false;
    const auto t0 = std::chrono::steady_clock::now();
    const std::uint32_t rows = std::min(bandRows, layout.height - y0);
    hooks.read(y0, rows);
    timings.readbackSeconds += secondsSince(t0);
    if (hooks.after) hooks.after(y0, rows);
    // The band is whole: the layout's count from here on (the shader's is the same unless a
    // pixel finished twice or never, which the image tests would see).
    finished = std::uint64_t{y0 + rows} * layout.width * samples;
    if (firstBandRows && pace.budget && bandSeconds > 0)
      next = timedBandRows(static_cast<double>(bandSteps) / bandSeconds,
                           static_cast<double>(bandSteps) / static_cast<double>(std::uint64_t{rows} * layout.width),
                           *pace.budget / layout.tilesPerGroup, layout.width, layout.bandHeight);
  }
  rays.primary = total;
  return true;
}

}  // namespace vkrt
