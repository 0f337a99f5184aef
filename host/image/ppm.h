// Binary PPM (P6) files, written atomically (temporary file + rename). The format of the
// course's guide: a text header, then the RGB bytes, row 0 at the top.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace vkrt {

// Writes `image` as "P6\nW H\n255\n" followed by its bytes, to a temporary file beside `path`
// renamed over it. Throws IoError (Interrupted between rows); no temporary file is left behind.
void writePpmAtomic(const Image& image, const std::string& path);

// The header alone ("P6", a "# KEYWORD TEXT" line per record, "W H", "255") into an open
// file; the rows follow it as they are (writeAll). Throws IoError.
void writePpmHeader(int fd, int width, int height, const std::vector<std::pair<std::string, std::string>>& records,
                    const std::string& path);

}  // namespace vkrt
