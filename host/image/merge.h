// `vkrt merge`: crops (images carrying a CropRecord) put back together into their full image.
// Knows nothing of rendering: the records say everything.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace vkrt {

struct MergeReport {
  int tiles = 0;
  std::uint64_t gapPixels = 0;   // pixels no tile covers (black; only with allowGaps)
};

// Reads every tile and places it where its record says. Throws UsageError for a set of tiles
// that does not make one image: a tile without a record (or a malformed one, or one whose
// size is not its rectangle's), tiles of different full images, overlapping tiles, and
// pixels no tile covers unless `allowGaps` (they stay black then). Throws IoError when a
// tile cannot be read.
Image mergeCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report = nullptr);

}  // namespace vkrt
