// Comparing two images for people and for CI: the metrics of `vkrt diff` and `--check`, the
// thresholds that decide the exit status, text and JSON reports.
#pragma once

#include <string>
#include <vector>

#include "compare/image_diff.h"

namespace vkrt {

// "--max-pixels-over STEPS:LIMIT": fails when more pixels than LIMIT (a count, or a share of
// the image with '%') differ by more than STEPS 8-bit steps in some channel.
struct PixelThreshold {
  int steps = 0;
  double limit = 0.0;
  bool percent = false;
  std::string text;   // as given
};

struct CheckThresholds {
  std::vector<PixelThreshold> pixelsOver;
  int maxDiff = -1;   // --max-diff N: fails when a channel differs by more than N steps; -1: unset
  // None given: any difference fails.
  bool any() const { return !pixelsOver.empty() || maxDiff >= 0; }
};

// Parses "2:0.1%" or "2:10". Throws UsageError (cli/options.h).
PixelThreshold parsePixelThreshold(const std::string& text);

// The thresholds that `diff` exceeds, as sentences; empty when it passes.
std::vector<std::string> failedThresholds(const ImageDiff& diff, const CheckThresholds& thresholds);

// A human report (several lines) and a one-line JSON object of the same numbers.
std::string diffReportText(const ImageDiff& diff);
std::string diffReportJson(const ImageDiff& diff, const std::vector<std::string>& failures);

}  // namespace vkrt
