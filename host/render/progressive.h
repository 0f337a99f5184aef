// Progressive rendering: a render as batches of samples, each a RadianceImage from a backend,
// accumulated into their mean weighted by sample count, until the samples asked for are done
// or the time is up. Knows nothing of the backends or of Vulkan: it drives a BatchRenderer.
#pragma once

#include <cstdint>
#include <functional>

#include "image/radiance_image.h"
#include "render/progress.h"

namespace vkrt {

// The samples [firstSample, firstSample + count) of every pixel.
struct SampleBatch {
  std::uint64_t firstSample = 0;
  std::uint32_t count = 1;
};

// The backends' seam: renders one batch (with the render's seed, which the renderer holds)
// into the mean of its samples, RadianceImage::samples = batch.count. `pixelProgress` (may be
// null) takes the backend's (pixels done, pixels total) within the batch.
using BatchRenderer = std::function<RadianceImage(
    const SampleBatch& batch, const std::function<void(std::uint64_t, std::uint64_t)>& pixelProgress)>;

struct ProgressiveOptions {
  std::uint64_t spp = 1;            // samples per pixel in all; 0: no limit (timeLimit must then be > 0)
  double timeLimitSeconds = 0;      // > 0: no batch is started that would end after this (one always runs)
  std::uint64_t firstSample = 0;    // the render's samples start here
  std::uint32_t maxBatchSamples = 1u << 16;
  // The first batch's samples. 1 lets a time limit learn the time per sample early; without a
  // time limit the pipeline asks for every sample at once, so that a backend's set-up (a
  // Vulkan pipeline) is paid once.
  std::uint32_t firstBatchSamples = 1;
  // Without a time limit batches grow (at most doubling) toward this length. Under one they
  // double until the last fills what is left: a backend reports progress and polls `stop`
  // within a batch, and its small batches are the slowest per sample (a Vulkan render's
  // setup, and lanes with few samples each), so a timed render's batches stay few.
  double targetBatchSeconds = 0.5;
  // Polled between batches (the backends poll it inside theirs): true stops early.
  std::function<bool()> stop;
  // Called after each batch with the running mean (may be empty).
  std::function<void(const RadianceImage& mean)> onBatch;
  // Drawn in samples ("N/M samples", or "N samples" under a time limit without spp).
  ProgressBar* progress = nullptr;
  // The clock, for tests (default: steady_clock seconds since an arbitrary start).
  std::function<double()> now;
};

struct ProgressiveReport {
  std::uint64_t samples = 0;   // samples per pixel rendered
  std::uint32_t batches = 0;
  bool timeUp = false;         // stopped by the time limit before spp
  bool stopped = false;        // stopped by `stop`
  double seconds = 0;
  // Under a time limit, how far its first batch ran past it (0 when within): one sample per
  // pixel, the least a render takes, took longer than the limit.
  double firstBatchPastLimit = 0;
};

// Renders batches until spp samples are done, the time limit leaves no room for another
// sample (per the last batch's time per sample), or `stop`. Batch sizes: 1 sample first (it
// includes the backend's warm-up), then doubling (at most, toward targetBatchSeconds, without
// a time limit), within what spp and the time left allow. The result is the weighted mean
// (samples = the total).
// The batch renderProgressive starts with.
SampleBatch firstBatch(const ProgressiveOptions& options);

RadianceImage renderProgressive(const BatchRenderer& render, const ProgressiveOptions& options,
                                ProgressiveReport* report = nullptr);

}  // namespace vkrt
