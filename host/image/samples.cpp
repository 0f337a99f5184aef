// The sample record and the weighted running mean of sample batches.
#include "image/samples.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "util/errors.h"

namespace vkrt {

std::uint64_t SampleRecord::total() const {
  std::uint64_t n = 0;
  for (const SampleRange& r : ranges) n += r.count;
  return n;
}

std::string formatSampleRecord(const SampleRecord& record) {
  char gamma[32];
  std::snprintf(gamma, sizeof gamma, "%.17g", record.gamma);
  std::string text = std::to_string(record.total()) + " gamma " + gamma +
                     (record.stratified ? " sampler stratified" : "") + " seeds";
  for (const SampleRange& r : record.ranges)
    text += " " + std::to_string(r.seed) + ":" + std::to_string(r.first) + "+" + std::to_string(r.count);
  return text;
}

namespace {

// A whole decimal number (digits only) that fits in `max`.
bool parseWhole(const std::string& s, std::uint64_t max, std::uint64_t& out) {
  if (s.empty() || s.size() > 20) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    const auto digit = static_cast<std::uint64_t>(c - '0');
    if (v > (max - digit) / 10) return false;
    v = v * 10 + digit;
  }
  out = v;
  return true;
}

}  // namespace

std::optional<SampleRecord> parseSampleRecord(const std::string& value) {
  std::istringstream in(value);
  std::string total, gammaWord, gamma, seedsWord;
  if (!(in >> total >> gammaWord >> gamma >> seedsWord) || gammaWord != "gamma") return std::nullopt;
  SampleRecord record;
  if (seedsWord == "sampler") {   // "sampler stratified": the one sampler named
    std::string sampler;
    if (!(in >> sampler >> seedsWord) || sampler != "stratified") return std::nullopt;
    record.stratified = true;
  }
  if (seedsWord != "seeds") return std::nullopt;
  try {
    std::size_t used = 0;
    record.gamma = std::stod(gamma, &used);
    if (used != gamma.size() || !(record.gamma > 0.0) || !std::isfinite(record.gamma)) return std::nullopt;
  } catch (const std::logic_error&) {
    return std::nullopt;
  }
  for (std::string word; in >> word;) {
    std::size_t colon = word.find(':'), plus = word.find('+');
    if (colon == std::string::npos || plus == std::string::npos || plus < colon) return std::nullopt;
    std::uint64_t seed = 0;
    SampleRange r;
    if (!parseWhole(word.substr(0, colon), 0xFFFFFFFFu, seed) ||
        !parseWhole(word.substr(colon + 1, plus - colon - 1), UINT64_MAX / 2, r.first) ||
        !parseWhole(word.substr(plus + 1), UINT64_MAX / 2, r.count) || r.count == 0)
      return std::nullopt;
    r.seed = static_cast<std::uint32_t>(seed);
    record.ranges.push_back(r);
  }
  // TOTAL is the sum of the counts, which must not wrap around.
  std::uint64_t n = 0, sum = 0;
  for (const SampleRange& r : record.ranges) {
    if (r.count > UINT64_MAX - sum) return std::nullopt;
    sum += r.count;
  }
  if (record.ranges.empty() || !parseWhole(total, UINT64_MAX, n) || n != sum) return std::nullopt;
  // The ranges of one record are disjoint: each pair once.
  for (std::size_t i = 0; i < record.ranges.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!sharedSample(SampleRecord{{record.ranges[i]}, 1.0}, SampleRecord{{record.ranges[j]}, 1.0}).empty())
        return std::nullopt;
  return record;
}

std::optional<SampleRecord> sampleRecordOf(const std::vector<std::pair<std::string, std::string>>& records) {
  for (const auto& [keyword, text] : records)
    if (keyword == kSamplesKeyword) return parseSampleRecord(text);
  return std::nullopt;
}

void setSampleRecord(std::vector<std::pair<std::string, std::string>>& records, const SampleRecord& record) {
  for (auto& [keyword, text] : records)
    if (keyword == kSamplesKeyword) text = formatSampleRecord(record);
}

std::string sharedSample(const SampleRecord& a, const SampleRecord& b) {
  for (const SampleRange& r : a.ranges)
    for (const SampleRange& s : b.ranges) {
      std::uint64_t lo = std::max(r.first, s.first), hi = std::min(r.first + r.count, s.first + s.count);
      if (r.seed == s.seed && lo < hi) return "seed " + std::to_string(r.seed) + ", sample " + std::to_string(lo);
    }
  return "";
}

void accumulateMean(RadianceImage& mean, RadianceImage batch) {
  if (mean.rgb.empty()) {
    std::vector<std::pair<std::string, std::string>> text = std::move(mean.text);
    mean = std::move(batch);
    if (!text.empty()) mean.text = std::move(text);
    return;
  }
  if (mean.width != batch.width || mean.height != batch.height)
    throw InternalError("accumulateMean: a " + std::to_string(batch.width) + "x" + std::to_string(batch.height) +
                        " batch into a " + std::to_string(mean.width) + "x" + std::to_string(mean.height) + " mean");
  const std::uint64_t total = mean.samples + batch.samples;
  const double w = static_cast<double>(batch.samples) / static_cast<double>(total);
  for (std::size_t i = 0; i < mean.rgb.size(); ++i) {
    double m = mean.rgb[i];
    mean.rgb[i] = static_cast<float>(m + (static_cast<double>(batch.rgb[i]) - m) * w);
  }
  mean.samples = total;
}

}  // namespace vkrt
