#include "gpu/band_dispatch.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "errors.h"
#include "gpu_types.h"
#include "timing.h"

namespace vkrt {
namespace {

// Rounds of dispatches per band before giving up (each round advances every unfinished
// invocation by the full step budget).
constexpr std::uint64_t kMaxRoundsPerBand = 1000000;

double clampBudget(double budget, std::uint32_t maxBudget) {
  return std::clamp(budget, std::min<double>(kMinStepBudget, maxBudget), static_cast<double>(maxBudget));
}

}  // namespace

std::uint32_t firstStepBudget(std::uint32_t maxBudget, std::uint64_t invocations, bool cpuDevice, double steps) {
  if (!cpuDevice || invocations == 0) return maxBudget;
  return static_cast<std::uint32_t>(clampBudget(steps / static_cast<double>(invocations), maxBudget));
}

std::uint32_t pacedStepBudget(std::uint32_t budget, double seconds, std::uint32_t maxBudget) {
  const double most = kMaxStepBudgetGrowth * budget;
  const double wanted = seconds > 0 ? budget * (kTargetDispatchSeconds / seconds) : most;
  return static_cast<std::uint32_t>(clampBudget(std::min(wanted, most), maxBudget));
}

bool dispatchBand(ComputePipeline& pipeline, const void* push, std::uint32_t& resume, std::uint32_t bandY0,
                  std::uint32_t groups, Buffer& counters, const std::function<bool()>& stop, VulkanTimings& timings,
                  RayCounts& rays, StepPace* pace) {
  auto* counter = static_cast<volatile gpu::GpuCounters*>(counters.mapped());
  resume = 0;
  std::uint64_t rounds = 0;
  do {
    if (++rounds > kMaxRoundsPerBand)
      throw InternalError("pixels of rows " + std::to_string(bandY0) + "+ still unfinished after " +
                          std::to_string(kMaxRoundsPerBand) + " dispatches");
    if (stop && stop()) return false;
    const auto t0 = std::chrono::steady_clock::now();
    pipeline.run(push, groups, &counters);
    const double s = secondsSince(t0);
    if (timings.dispatches == 0) {
      timings.firstDispatchSeconds = s;
    } else {
      timings.dispatchSeconds += s;
      if (pace && pace->budget) *pace->budget = pacedStepBudget(*pace->budget, s, pace->maxBudget);
    }
    ++timings.dispatches;
    timings.suspensions += counter->suspended;
    rays.shadow += counter->shadowRays;
    rays.secondary += counter->secondaryRays;
    rays.nonFinite += counter->nonFinite;
    counter->shadowRays = 0;
    counter->secondaryRays = 0;
    counter->nonFinite = 0;
    resume = 1;
  } while (counter->suspended > 0);
  ++timings.bands;
  return true;
}

}  // namespace vkrt
