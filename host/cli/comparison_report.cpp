// The comparison of two images as diff, --check and --compare report it
// (host/cli/comparison_report.h).
#include "cli/comparison_report.h"

#include <cmath>
#include <cstdio>

#include "cli/exit_status.h"
#include "compare/image_check.h"
#include "image/atomic_file.h"
#include "image/image_file.h"
#include "compare/image_diff.h"
#include "util/json.h"

namespace vkrt {

// The heatmap of --diff, when asked for, in the 8-bit format of its name.
void writeHeatmap(const ComparisonOptions& o, const ImageDiff& diff) {
  if (o.heatmapPath) writeImageAtomic(differenceHeatmap(diff, o.heatmapScale), *o.heatmapPath);
}

// --diff FILE: an output of the run, checked (and its folder's writability) before any
// image is read or rendered.
void claimHeatmap(const ComparisonOptions& o, RunFiles& files) {
  if (!o.heatmapPath) return;
  files.addOutput(*o.heatmapPath, "the heatmap (--diff)");
  checkOutputWritable(*o.heatmapPath);
}

// The metrics, the heatmap (written, and named with its scale) and the failures, as text.
void printComparisonText(const ComparisonOptions& o, const ImageDiff& diff, const std::vector<std::string>& failures) {
  writeHeatmap(o, diff);
  std::printf("%s", diffReportText(diff).c_str());
  if (o.heatmapPath)
    std::printf("  heatmap     %s (black: equal; blue 1/255 ... red %d/255 or more)\n", o.heatmapPath->c_str(),
                o.heatmapScale);
  for (const std::string& f : failures) std::printf("FAIL: %s\n", f.c_str());
}

// Compares `actual` with `expected` (diff and --check): the report on stdout (text or JSON),
// the heatmap if asked for; kExitDiffers when a threshold is exceeded. Throws IoError.
// `linear`: for two linear-float images, their difference in radiance units, reported beside
// the 8-bit figures (which the thresholds judge).
int reportComparison(const ComparisonOptions& o, const Image& actual, const Image& expected,
                     const std::string& what, const std::optional<LinearDifference>& linear) {
  if (actual.width != expected.width || actual.height != expected.height) {
    std::string msg = "sizes differ: " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                      " vs " + std::to_string(expected.width) + "x" + std::to_string(expected.height);
    if (o.json)
      std::printf("{\"pass\":false,\"failures\":[%s]}\n", jsonQuoted(msg).c_str());
    else
      std::printf("%s: FAIL: %s\n", what.c_str(), msg.c_str());
    return kExitDiffers;
  }
  ImageDiff diff = compare(actual, expected);
  std::vector<std::string> failures = failedThresholds(diff, o.thresholds);
  if (o.json) {
    writeHeatmap(o, diff);
    std::string json = diffReportJson(diff, failures);
    if (linear) {
      // JSON has no infinity: a difference without bound (a NaN or infinite channel) is null.
      auto number = [](double v) {
        char s[32];
        std::snprintf(s, sizeof s, "%.9g", v);
        return std::isfinite(v) ? std::string(s) : std::string("null");
      };
      json = json.substr(0, json.size() - 1) + ",\"linear_max_diff\":" + number(linear->maxDiff) +
             ",\"linear_rmse\":" + number(linear->rmse) + "}";
    }
    std::printf("%s\n", json.c_str());
  } else {
    std::printf("%s\n", what.c_str());
    if (linear)
      std::printf("  linear      max diff %.6g, RMSE %.6g (radiance, before encoding)\n", linear->maxDiff, linear->rmse);
    printComparisonText(o, diff, failures);
    if (failures.empty()) std::printf("PASS\n");
  }
  return failures.empty() ? kExitOk : kExitDiffers;
}

}  // namespace vkrt
