// The dispatch loop both Vulkan renderers run per band of the image: dispatch, then dispatch
// again with `resume` set until no pixel of the band is left suspended (the loop budget of
// llvmpipe, gpu_types.h).
#pragma once

#include <cstdint>
#include <functional>

#include "cpu/reference.h"
#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/vulkan_renderer.h"

namespace vkrt {

// Runs the band whose push constants are `push` (bandY0 already set; `resume` is a field of
// them, set here). `counters` is the GpuCounters buffer: after each dispatch its suspended
// count goes into the timings and its ray counts are added into `rays` and zeroed (the
// shader's counters are 32-bit; one dispatch traces fewer than 2^32 rays). Returns false,
// without finishing the band, when `stop` asks before a dispatch. Throws InternalError when a
// band never finishes (a bug guard: every pixel's work is bounded).
bool dispatchBand(ComputePipeline& pipeline, const void* push, std::uint32_t& resume, std::uint32_t bandY0,
                  std::uint32_t groups, Buffer& counters, const std::function<bool()>& stop, VulkanTimings& timings,
                  RayCounts& rays);

}  // namespace vkrt
