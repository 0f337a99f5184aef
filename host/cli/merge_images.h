// vkrt merge -o OUT TILE ...: crops (--crop) back into their full image, or sample batches of
// one path-traced render averaged (image/merge.h); the tiles are inputs, the merged image the
// output, written whole or not at all.
#pragma once

#include "cli/options.h"

namespace vkrt {

// Throws UsageError (tiles that do not fit together), IoError.
int mergeImages(const MergeOptions& options);

}  // namespace vkrt
