// The dispatch loop both Vulkan renderers run per band of the image: dispatch, then dispatch
// again with `resume` set until no pixel of the band is left suspended (the loop budget of
// llvmpipe, gpu_types.h).
#pragma once

#include <cstdint>
#include <functional>

#include "render/ray_counts.h"
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
//
// `pace` (may be null) paces the dispatches by time (StepPace).
struct StepPace;
bool dispatchBand(ComputePipeline& pipeline, const void* push, std::uint32_t& resume, std::uint32_t bandY0,
                  std::uint32_t groups, Buffer& counters, const std::function<bool()>& stop, VulkanTimings& timings,
                  RayCounts& rays, StepPace* pace = nullptr);

// The step budget of a render's dispatches, paced by time so that `stop` is polled a few times
// a second whatever the device and the image: a long dispatch cannot be interrupted, and on a
// CPU device a dispatch of every pixel at the full budget takes seconds to minutes. `budget`
// points at the stepBudget of the mapped GpuRenderParams the shader reads. On a CPU device the
// first dispatch gets about the renderer's first-dispatch steps in all (a 640x480 Whitted
// image at the whole budget; a path band at a budget that makes its later rounds few: a
// suspension round costs time, and the first dispatch includes the JIT compile anyway); a
// GPU's gets the whole budget. After each later dispatch the budget follows
// kTargetDispatchSeconds / the dispatch's seconds, growing at most kMaxStepBudgetGrowth times,
// within [kMinStepBudget, maxBudget]. Where a pixel is suspended changes no bit of it
// (gpu_types.h), so the pace changes no image. An explicit budget (a test's) is not paced.
inline constexpr double kTargetDispatchSeconds = 0.4;
inline constexpr double kWhittedFirstDispatchSteps = 160e6;
inline constexpr double kPathFirstDispatchSteps = 80e6;
inline constexpr std::uint32_t kMinStepBudget = 16;
inline constexpr double kMaxStepBudgetGrowth = 4.0;
struct StepPace {
  std::uint32_t* budget = nullptr;
  std::uint32_t maxBudget = 0;
};
// The budget of a render's first dispatch of `invocations` taking about `steps` in all on a
// CPU device (see StepPace).
std::uint32_t firstStepBudget(std::uint32_t maxBudget, std::uint64_t invocations, bool cpuDevice, double steps);
// The next budget after a dispatch of `seconds` at `budget` (see StepPace).
std::uint32_t pacedStepBudget(std::uint32_t budget, double seconds, std::uint32_t maxBudget);

}  // namespace vkrt
