// The comparison of two images as diff, --check and --compare report it: the figures on
// stdout (text or JSON), the failed thresholds, the heatmap of --diff. Renders nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/options.h"
#include "cli/run_files.h"
#include "compare/image_diff.h"
#include "image/image.h"
#include "image/image_read.h"   // LinearDifference

namespace vkrt {

// The heatmap of --diff, when asked for, in the 8-bit format of its name.
void writeHeatmap(const ComparisonOptions& o, const ImageDiff& diff);

// --diff FILE: an output of the run, checked (and its folder's writability) before any
// image is read or rendered.
void claimHeatmap(const ComparisonOptions& o, RunFiles& files);

// The metrics, the heatmap (written, and named with its scale) and the failures, as text.
void printComparisonText(const ComparisonOptions& o, const ImageDiff& diff, const std::vector<std::string>& failures);

// Compares `actual` with `expected` (diff and --check): the report on stdout (text or JSON),
// the heatmap if asked for; kExitDiffers when a threshold is exceeded. Throws IoError.
// `linear`: for two linear-float images, their difference in radiance units, reported beside
// the 8-bit figures (which the thresholds judge).
int reportComparison(const ComparisonOptions& o, const Image& actual, const Image& expected, const std::string& what,
                     const std::optional<LinearDifference>& linear = std::nullopt);

}  // namespace vkrt
