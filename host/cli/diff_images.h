// vkrt diff A B: two images compared (linear-float ones also in radiance units), the report
// on stdout, the heatmap of --diff written.
#pragma once

#include "cli/options.h"

namespace vkrt {

// kExitDiffers when a threshold is exceeded. Throws IoError.
int diffImages(const DiffOptions& options);

}  // namespace vkrt
