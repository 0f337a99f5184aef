// The comparison of two images as diff, --check and --compare report it: the figures on
// stdout (text or JSON), the failed thresholds, the heatmap of --diff. Renders nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/options.h"
#include "cli/run_files.h"
#include "compare/flip.h"
#include "compare/image_diff.h"
#include "image/image.h"
#include "image/image_read.h"   // LinearDifference

namespace vkrt {

// Two images of one size compared: the 8-bit figures and FLIP's map and figures.
struct ImageComparison {
  ImageDiff diff;
  FlipMap flipMap;
  FlipStats flip;
};

// Compares `actual` with `expected` (of one size): FLIP is HDR-FLIP of the two linear-float
// images when both are given, else LDR-FLIP of the 8-bit ones.
// FLIP is computed for `pixelsPerDegree` (--pixels-per-degree).
ImageComparison compareImages(const Image& actual, const Image& expected, double pixelsPerDegree,
                              const RadianceImage* actualRadiance = nullptr,
                              const RadianceImage* expectedRadiance = nullptr);

// The heatmap of --diff and the FLIP map of --flip-map, those asked for, in the 8-bit format
// of their names.
void writeHeatmap(const ComparisonOptions& o, const ImageComparison& c);

// --diff FILE and --flip-map FILE: outputs of the run, checked (and their folders'
// writability) before any image is read or rendered.
void claimHeatmap(const ComparisonOptions& o, RunFiles& files);

// The metrics, the heatmap and FLIP map (written, and named) and the failures, as text.
void printComparisonText(const ComparisonOptions& o, const ImageComparison& c, const std::vector<std::string>& failures);

// Compares `actual` with `expected` (diff and --check): the report on stdout (text or JSON),
// the heatmap if asked for; kExitDiffers when a threshold is exceeded. Throws IoError.
// `linear`: for two linear-float images, their difference in radiance units, reported beside
// the 8-bit figures (which the thresholds judge); `actualRadiance` and `expectedRadiance`,
// both given, are those images, for HDR-FLIP.
int reportComparison(const ComparisonOptions& o, const Image& actual, const Image& expected, const std::string& what,
                     const std::optional<LinearDifference>& linear = std::nullopt,
                     const RadianceImage* actualRadiance = nullptr, const RadianceImage* expectedRadiance = nullptr);

}  // namespace vkrt
