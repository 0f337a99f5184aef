// The dispatch loop both Vulkan renderers run per band of the image: dispatch, then dispatch
// again with `resume` set until no pixel of the band is left suspended (the loop budget of
// llvmpipe, gpu_types.h).
#pragma once

#include <cstdint>
#include <functional>

#include "util/ray_counts.h"
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
// What a dispatch did (GpuCounters): the pixels (raytrace.comp) or pixel samples
// (pathtrace.comp) it finished, the steps it ran, and
// its seconds.
struct DispatchDone {
  std::uint64_t finished = 0, steps = 0;
  double seconds = 0;
};

// `pace` (may be null) paces the dispatches by time (StepPace). `done` (may be empty) takes
// what each dispatch did.
struct StepPace;
bool dispatchBand(ComputePipeline& pipeline, const void* push, std::uint32_t& resume, std::uint32_t bandY0,
                  std::uint32_t groups, Buffer& counters, const std::function<bool()>& stop, VulkanTimings& timings,
                  RayCounts& rays, StepPace* pace = nullptr,
                  const std::function<void(const DispatchDone&)>& done = {});

// The step budget of a render's dispatches, paced by time so that `stop` is polled a few times
// a second and the progress bar moves, whatever the device and the image: a long dispatch
// cannot be interrupted, and on a CPU device a dispatch of every pixel at the full budget
// takes seconds to minutes. `budget` points at the stepBudget of the mapped GpuRenderParams
// the shader reads. On a CPU device the first dispatch gets about the renderer's
// first-dispatch steps in all (a 640x480 Whitted image at the whole budget; a path band at
// about a quarter of a second's steps on lavapipe, its JIT compile besides); a GPU's gets the
// whole budget. After each dispatch the budget follows kTargetDispatchSeconds / the
// dispatch's seconds, growing at most kMaxStepBudgetGrowth times, within [kMinStepBudget,
// maxBudget]. A band's first dispatch runs every pixel of it, its later ones only those left
// suspended, fewer and fewer: so a band starts at the budget its predecessor started at (as
// paced by that dispatch), not at the one its last few pixels grew (which on lavapipe made a
// dispatch of a whole band at 16 times the budget take seconds: bench/README.md, "Latest
// figures: first render, shader variants, responsiveness"). Where a pixel is suspended
// changes no bit of it (gpu_types.h), so the pace changes no image. An explicit budget (a
// test's) is not paced.
inline constexpr double kTargetDispatchSeconds = 0.3;
inline constexpr double kWhittedFirstDispatchSteps = 160e6;
inline constexpr double kPathFirstDispatchSteps = 20e6;
inline constexpr std::uint32_t kMinStepBudget = 16;
inline constexpr double kMaxStepBudgetGrowth = 4.0;
struct StepPace {
  std::uint32_t* budget = nullptr;
  std::uint32_t maxBudget = 0;
  std::uint32_t bandStartBudget = 0;   // 0 until a band's first dispatch has been timed
  // Before a dispatch (`bandStart`: the band's first) and after it, `seconds` long.
  void before(bool bandStart);
  void after(bool bandStart, double seconds);
};
// Bands sized by time (the path renderer's, paced): rows of the next band such that one
// dispatch runs each of its pixels for as many steps as a pixel of the last band took
// (`stepsPerPixel`; at most `budget`, the steps a dispatch runs per pixel: its budget over the
// pixels an invocation takes in turn), at `stepsPerSecond`, in about
// kTargetDispatchSeconds: so most pixels finish in one dispatch, instead of every pixel of a
// band of the memory's size suspending every few hundred steps (on lavapipe a suspension costs
// a pixel many steps' time: bench/README.md, "Latest figures: first render, shader variants,
// responsiveness"). A multiple
// of the tile's rows within [tile, maxRows].
std::uint32_t timedBandRows(double stepsPerSecond, double stepsPerPixel, std::uint32_t budget, std::uint32_t width,
                            std::uint32_t maxRows);
// The first band of a time-sized render: on a CPU device the rows whose pixels run `maxBudget`
// steps each (the full budget over the pixels an invocation takes) in about `steps` in all
// (kPathFirstDispatchSteps), on a GPU `maxRows`.
std::uint32_t firstTimedBandRows(std::uint32_t maxBudget, std::uint32_t width, std::uint32_t maxRows, bool cpuDevice,
                                 double steps);

// The budget of a render's first dispatch of `invocations` taking about `steps` in all on a
// CPU device (see StepPace).
std::uint32_t firstStepBudget(std::uint32_t maxBudget, std::uint64_t invocations, bool cpuDevice, double steps);
// The next budget after a dispatch of `seconds` at `budget` (see StepPace).
std::uint32_t pacedStepBudget(std::uint32_t budget, double seconds, std::uint32_t maxBudget);

}  // namespace vkrt
