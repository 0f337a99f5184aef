// Comparing two images for people and for CI: the metrics of `vkrt diff` and `--check`, the
// thresholds that decide the exit status, text and JSON reports.
#pragma once

#include <string>
#include <vector>

#include "compare/flip.h"
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
  double maxFlip = -1.0;   // --max-flip X: fails when the mean FLIP error exceeds X; -1: unset
  // --pixels-per-degree PPD: the viewing condition FLIP is computed for (not a threshold).
  double pixelsPerDegree = kFlipDefaultPixelsPerDegree;
  // None given: any difference fails.
  bool any() const { return !pixelsOver.empty() || maxDiff >= 0 || maxFlip >= 0.0; }
};

// Parses "2:0.1%" or "2:10". Throws UsageError (cli/options.h).
PixelThreshold parsePixelThreshold(const std::string& text);

// Parses --max-flip's value, a number from 0 to 1. Throws UsageError.
double parseFlipThreshold(const std::string& text);

// Parses --pixels-per-degree's value, a number above 0 and at most 1000. Throws UsageError.
double parsePixelsPerDegree(const std::string& text);

// The thresholds that `diff` (and `flip`, FLIP's figures of the same two images) exceed, as
// sentences; empty when it passes. --max-flip judges `flip.mean`.
std::vector<std::string> failedThresholds(const ImageDiff& diff, const FlipStats& flip,
                                          const CheckThresholds& thresholds);

// FLIP's line of the text report: "LDR-FLIP mean 0.0123, median ..." (HDR-FLIP with its
// exposures), and its JSON object: {"kind":"ldr","mean":...,"median":...,"p95":...,"p99":...,
// "max":...,"pixels_per_degree":67.02} (HDR adds "start_exposure", "stop_exposure", "exposures").
std::string flipReportText(const FlipStats& flip);
std::string flipReportJson(const FlipStats& flip);

// A human report (several lines) and a one-line JSON object of the same numbers.
std::string diffReportText(const ImageDiff& diff, const FlipStats& flip);
std::string diffReportJson(const ImageDiff& diff, const FlipStats& flip, const std::vector<std::string>& failures);

}  // namespace vkrt
