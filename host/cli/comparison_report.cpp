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

ImageComparison compareImages(const Image& actual, const Image& expected, double pixelsPerDegree,
                              const RadianceImage* actualRadiance, const RadianceImage* expectedRadiance) {
  ImageComparison c;
  c.diff = compare(actual, expected);
  const bool hdr = actualRadiance && expectedRadiance;
  FlipExposures exposures;
  c.flipMap = hdr ? hdrFlip(*actualRadiance, *expectedRadiance, &exposures, pixelsPerDegree)
                  : ldrFlip(actual, expected, pixelsPerDegree);
  c.flip = flipStats(c.flipMap);
  c.flip.pixelsPerDegree = pixelsPerDegree;
  c.flip.hdr = hdr;
  c.flip.exposures = exposures;
  return c;
}

// The heatmap of --diff and the FLIP map of --flip-map, those asked for, in the 8-bit format
// of their names.
void writeHeatmap(const ComparisonOptions& o, const ImageComparison& c) {
  if (o.heatmapPath) writeImageAtomic(differenceHeatmap(c.diff, o.heatmapScale), *o.heatmapPath);
  if (o.flipMapPath) writeImageAtomic(flipMagmaImage(c.flipMap), *o.flipMapPath);
}

// --diff FILE and --flip-map FILE: outputs of the run, checked (and their folders'
// writability) before any image is read or rendered.
void claimHeatmap(const ComparisonOptions& o, RunFiles& files) {
  if (o.heatmapPath) {
    files.addOutput(*o.heatmapPath, "the heatmap (--diff)");
    checkOutputWritable(*o.heatmapPath);
  }
  if (o.flipMapPath) {
    files.addOutput(*o.flipMapPath, "the FLIP map (--flip-map)");
    checkOutputWritable(*o.flipMapPath);
  }
}

// The metrics, the heatmap and FLIP map (written, and named) and the failures, as text.
void printComparisonText(const ComparisonOptions& o, const ImageComparison& c, const std::vector<std::string>& failures) {
  writeHeatmap(o, c);
  std::printf("%s", diffReportText(c.diff, c.flip).c_str());
  if (o.heatmapPath)
    std::printf("  heatmap     %s (black: equal; blue 1/255 ... red %d/255 or more)\n", o.heatmapPath->c_str(),
                o.heatmapScale);
  if (o.flipMapPath)
    std::printf("  FLIP map    %s (magma: black no error ... pale yellow 1)\n", o.flipMapPath->c_str());
  for (const std::string& f : failures) std::printf("FAIL: %s\n", f.c_str());
}

// Compares `actual` with `expected` (diff and --check): the report on stdout (text or JSON),
// the heatmap if asked for; kExitDiffers when a threshold is exceeded. Throws IoError.
// `linear`: for two linear-float images, their difference in radiance units, reported beside
// the 8-bit figures (which the thresholds judge).
int reportComparison(const ComparisonOptions& o, const Image& actual, const Image& expected,
                     const std::string& what, const std::optional<LinearDifference>& linear,
                     const RadianceImage* actualRadiance, const RadianceImage* expectedRadiance) {
  if (actual.width != expected.width || actual.height != expected.height) {
    std::string msg = "sizes differ: " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                      " vs " + std::to_string(expected.width) + "x" + std::to_string(expected.height);
    if (o.json)
      std::printf("{\"pass\":false,\"failures\":[%s]}\n", jsonQuoted(msg).c_str());
    else
      std::printf("%s: FAIL: %s\n", what.c_str(), msg.c_str());
    return kExitDiffers;
  }
  ImageComparison c = compareImages(actual, expected, o.thresholds.pixelsPerDegree, actualRadiance, expectedRadiance);
  std::vector<std::string> failures = failedThresholds(c.diff, c.flip, o.thresholds);
  if (o.json) {
    writeHeatmap(o, c);
    std::string json = diffReportJson(c.diff, c.flip, failures);
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
    printComparisonText(o, c, failures);
    if (failures.empty()) std::printf("PASS\n");
  }
  return failures.empty() ? kExitOk : kExitDiffers;
}

}  // namespace vkrt
