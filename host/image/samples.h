// Sample batches: the running mean that accumulates them, and the record (`vkrt-samples`) an
// image of a path-traced render carries so that `vkrt merge` can average batches rendered
// apart. Knows nothing of rendering.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/radiance_image.h"

namespace vkrt {

// Which samples an image is the mean of: for each seed, the sample indices [first, first +
// count) of every pixel (gpu_rng.h); and the gamma its output encodes with.
struct SampleRange {
  std::uint32_t seed = 0;
  std::uint64_t first = 0, count = 0;
};

struct SampleRecord {
  std::vector<SampleRange> ranges;   // disjoint
  double gamma = 1.0;
  bool stratified = false;           // --sampler stratified (else independent samples)
  std::uint64_t total() const;
};

// The keyword of the record (a PNG tEXt chunk, a PPM header comment, a PFM trailer line).
inline constexpr const char* kSamplesKeyword = "vkrt-samples";

// "TOTAL gamma G [sampler stratified ]seeds SEED:FIRST+COUNT[ SEED:FIRST+COUNT ...]", e.g.
// "64 gamma 2.2 seeds 7:0+64" (independent samples: the record as it was before the sampler).
std::string formatSampleRecord(const SampleRecord& record);

// The record's value back; nullopt when malformed (TOTAL not the sum, no range, an empty range,
// a gamma not > 0).
std::optional<SampleRecord> parseSampleRecord(const std::string& value);

// The record among an image's records (RadianceImage::text, Image::text), parsed; nullopt
// when it has none or a malformed one.
std::optional<SampleRecord> sampleRecordOf(const std::vector<std::pair<std::string, std::string>>& records);
// Replaces the value of the record among `records` (which must hold one).
void setSampleRecord(std::vector<std::pair<std::string, std::string>>& records, const SampleRecord& record);

// The first sample the two records share, as "seed K, sample N"; "" when they share none.
std::string sharedSample(const SampleRecord& a, const SampleRecord& b);

// mean := the mean of `mean` (mean.samples samples) and `batch` (batch.samples samples),
// weighted by those counts, per channel in double, stored as float; mean.samples becomes the
// sum. A `mean` with no pixels takes `batch` as it is (moved: no second copy of a large image).
// The sizes must agree (throws InternalError otherwise: a bug of the caller).
void accumulateMean(RadianceImage& mean, RadianceImage batch);

}  // namespace vkrt
