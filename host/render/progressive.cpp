// The batch loop of a progressive render.
#include "render/progressive.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "util/counted.h"
#include "util/errors.h"
#include "image/samples.h"

namespace vkrt {
namespace {

// The samples of the next batch, `done` being rendered and `next` the size it grows to: within
// what spp leaves and maxBatchSamples.
std::uint32_t batchSamples(const ProgressiveOptions& options, std::uint64_t done, std::uint32_t next) {
  const std::uint64_t left = options.spp == 0 ? UINT64_MAX : options.spp - done;
  return static_cast<std::uint32_t>(std::min<std::uint64_t>({next, left, options.maxBatchSamples}));
}

}  // namespace

SampleBatch firstBatch(const ProgressiveOptions& options) {
  return {options.firstSample, batchSamples(options, 0, std::max(options.firstBatchSamples, 1u))};
}

RadianceImage renderProgressive(const BatchRenderer& render, const ProgressiveOptions& options,
                                ProgressiveReport* report) {
  if (options.spp == 0 && !(options.timeLimitSeconds > 0))
    throw InternalError("renderProgressive: neither a sample count nor a time limit");
  auto steadyNow = [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  };
  const std::function<double()> now = options.now ? options.now : std::function<double()>(steadyNow);
  const double start = now();
  const bool timed = options.timeLimitSeconds > 0;

  RadianceImage mean;
  mean.samples = 0;
  ProgressiveReport r;
  std::uint32_t next = std::max(options.firstBatchSamples, 1u);
  for (;;) {
    const std::uint32_t count = batchSamples(options, r.samples, next);
    const std::uint64_t done = r.samples;
    auto pixelProgress = [&](std::uint64_t pixelsDone, std::uint64_t pixelsTotal) {
      if (!options.progress || pixelsTotal == 0) return;
      double samplesNow = static_cast<double>(done) +
                          count * static_cast<double>(pixelsDone) / static_cast<double>(pixelsTotal);
      const auto samplesDone = static_cast<std::uint64_t>(samplesNow);
      std::string note = options.spp ? std::to_string(samplesDone) + "/" + counted(options.spp, "sample", "samples")
                                     : counted(samplesDone, "sample", "samples");
      double fraction = options.spp ? samplesNow / static_cast<double>(options.spp) : 0.0;
      if (timed) fraction = std::max(fraction, (now() - start) / options.timeLimitSeconds);
      constexpr std::uint64_t kScale = 1000000;
      options.progress->update(static_cast<std::uint64_t>(std::min(fraction, 1.0) * kScale), kScale, note);
    };
    const double t0 = now();
    RadianceImage batch = render(SampleBatch{options.firstSample + done, count}, pixelProgress);
    const double batchSeconds = now() - t0;
    if (options.stop && options.stop()) {   // an interrupted batch is incomplete: not added
      r.stopped = true;
      break;
    }
    if (batch.samples != count)
      throw InternalError("a backend returned " + std::to_string(batch.samples) + " samples for a batch of " +
                          std::to_string(count));
    accumulateMean(mean, std::move(batch));
    if (options.onBatch) options.onBatch(mean);
    r.samples += count;
    ++r.batches;
    if (timed && r.batches == 1) r.firstBatchPastLimit = std::max(now() - start - options.timeLimitSeconds, 0.0);
    if (options.spp != 0 && r.samples >= options.spp) break;
    // The next batch: toward targetBatchSeconds, at most twice this one; under a time limit
    // nine tenths of what fits in the time left (the tenth for the estimate's error; the next
    // batch takes the rest), at least twice this one where that fits.
    const double perSample = std::max(batchSeconds / count, 1e-9);
    double want = std::clamp(std::floor(options.targetBatchSeconds / perSample), 1.0, 2.0 * count);
    if (timed) {
      const double remaining = options.timeLimitSeconds - (now() - start);
      const double fits = std::floor(remaining / perSample);
      if (fits < 1.0) {
        r.timeUp = true;
        break;
      }
      want = std::min(std::max(std::floor(0.9 * fits), 2.0 * count), fits);
    }
    next = static_cast<std::uint32_t>(std::min<double>(want, options.maxBatchSamples));
  }
  r.seconds = now() - start;
  if (report) *report = r;
  return mean;
}

}  // namespace vkrt
