// An image given where a scene file is expected (`vkrt a.png`, `vkrt dif a.png b.png`):
// found before anything is read as a scene, so that the message says what the file is.
#pragma once

#include <optional>
#include <string>

namespace vkrt {

// "PNG", "PPM", "PFM" or "JPEG" when `path` is an image: a regular file that starts as one
// (the PNG signature, "P6"/"P3", "PF"/"Pf" and a blank, the JPEG marker), or, when no such
// file can be read, a name ending in .png, .ppm, .pfm, .jpg or .jpeg (any case). Nothing for
// anything else: a text file is a scene whatever its name. Reads at most 8 bytes, and only
// from a regular file (a FIFO's bytes are left for the parser).
std::optional<std::string> imageKind(const std::string& path);

}  // namespace vkrt
