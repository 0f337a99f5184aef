// PNG files: atomic writing (temporary file + rename) and reading (for tests and diffs).
#pragma once

#include <string>

#include "errors.h"
#include "image/atomic_file.h"   // checkOutputWritable
#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// Writes `image` to a temporary file beside `path` and renames it over `path`, so an existing
// file is replaced whole or not at all. Throws IoError; no temporary file is left behind.
void writePngAtomic(const Image& image, const std::string& path);

// The same for a render, each row encoded with `gamma` (image/encode.h) as it is written: no
// 8-bit copy of the image is made.
void writePngAtomic(const RadianceImage& image, double gamma, const std::string& path);

// Reads a PNG, a binary PPM (P6) or a JPEG as 8-bit RGB. Throws IoError.
Image readImage(const std::string& path);

}  // namespace vkrt
