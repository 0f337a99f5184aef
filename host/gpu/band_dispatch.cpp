#include "gpu/band_dispatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "util/errors.h"
#include "gpu_types.h"
#include "util/timing.h"

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

namespace {

// `rows` down to a multiple of the tile's, within [tile, maxRows] (maxRows a multiple of it).
std::uint32_t tileRows(double rows, std::uint32_t maxRows) {
  const double tile = gpu::kWorkgroupSize;
  if (!(rows >= tile)) return gpu::kWorkgroupSize;
  return static_cast<std::uint32_t>(std::max(std::floor(std::min(rows, static_cast<double>(maxRows)) / tile) * tile, tile));
}

}  // namespace

std::uint32_t timedBandRows(double stepsPerSecond, double stepsPerPixel, std::uint32_t budget, std::uint32_t width,
                            std::uint32_t maxRows) {
  const double perPixel = std::clamp(stepsPerPixel, 1.0, static_cast<double>(std::max(budget, 1u)));
  if (!(stepsPerSecond > 0) || width == 0) return tileRows(0, maxRows);
  return tileRows(kTargetDispatchSeconds * stepsPerSecond / (perPixel * width), maxRows);
}

std::uint32_t firstTimedBandRows(std::uint32_t maxBudget, std::uint32_t width, std::uint32_t maxRows, bool cpuDevice,
                                 double steps) {
  if (!cpuDevice || width == 0 || maxBudget == 0) return maxRows;
  return tileRows(steps / (static_cast<double>(maxBudget) * width), maxRows);
}

void StepPace::before(bool bandStart) {
  if (budget && bandStart && bandStartBudget) *budget = bandStartBudget;
}

void StepPace::after(bool bandStart, double seconds) {
  if (!budget) return;
  *budget = pacedStepBudget(*budget, seconds, maxBudget);
  if (bandStart) bandStartBudget = *budget;
}

std::uint32_t pacedStepBudget(std::uint32_t budget, double seconds, std::uint32_t maxBudget) {
  const double most = kMaxStepBudgetGrowth * budget;
  const double wanted = seconds > 0 ? budget * (kTargetDispatchSeconds / seconds) : most;
  return static_cast<std::uint32_t>(clampBudget(std::min(wanted, most), maxBudget));
}

bool dispatchBand(ComputePipeline& pipeline, const void* push, std::uint32_t& resume, std::uint32_t bandY0,
                  std::uint32_t groups, Buffer& counters, const std::function<bool()>& stop, VulkanTimings& timings,
                  RayCounts& rays, StepPace* pace, const std::function<void(const DispatchDone&)>& done) {
  auto* counter = static_cast<volatile gpu::GpuCounters*>(counters.mapped());
  resume = 0;
  std::uint64_t rounds = 0;
  do {
    if (++rounds > kMaxRoundsPerBand)
      throw InternalError("pixels of rows " + std::to_string(bandY0) + "+ still unfinished after " +
                          std::to_string(kMaxRoundsPerBand) + " dispatches");
    if (stop && stop()) return false;
    if (pace) pace->before(resume == 0);
    const auto t0 = std::chrono::steady_clock::now();
    pipeline.run(push, groups, &counters);
    const double s = secondsSince(t0);
    (timings.dispatches == 0 ? timings.firstDispatchSeconds : timings.dispatchSeconds) += s;
    // (The first dispatch's time includes the JIT compile: the budget it paces is smaller than
    // it need be, and grows again.)
    if (pace) pace->after(resume == 0, s);
    ++timings.dispatches;
    timings.suspensions += counter->suspended;
    rays.shadow += counter->shadowRays;
    rays.secondary += counter->secondaryRays;
    rays.nonFinite += counter->nonFinite;
    counter->shadowRays = 0;
    counter->secondaryRays = 0;
    counter->nonFinite = 0;
    rays.boxTests += std::uint64_t{counter->boxTestsHigh} << 32 | counter->boxTestsLow;
    rays.primitiveTests += std::uint64_t{counter->primitiveTestsHigh} << 32 | counter->primitiveTestsLow;
    counter->boxTestsLow = 0;
    counter->boxTestsHigh = 0;
    counter->primitiveTestsLow = 0;
    counter->primitiveTestsHigh = 0;
    const DispatchDone did{counter->finished, counter->steps, s};
    counter->finished = 0;
    counter->steps = 0;
    if (done) done(did);
    resume = 1;
  } while (counter->suspended > 0);
  ++timings.bands;
  return true;
}

}  // namespace vkrt
