// An image given where a scene file is expected (`vkrt a.png`, `vkrt dif a.png b.png`):
// found before anything is read as a scene, so that the message says what the file is.
#pragma once

#include <optional>
#include <string>

namespace vkrt {

// The name of a format of image/image_file.h's table ("PNG"), or "JPEG" or "PPM" for an
// ASCII PPM (read, not written), when `path` is an image: a regular file that starts as one
// (ImageFormat::isFile; the JPEG marker; "P3" and a blank), or, when no such file can be
// read, a name with an extension of the table, .jpg or .jpeg (any case). Nothing for anything
// else: a text file is a scene whatever its name. Reads only the first bytes of a regular
// file (a FIFO's bytes are left for the parser).
std::optional<std::string> imageKind(const std::string& path);

}  // namespace vkrt
