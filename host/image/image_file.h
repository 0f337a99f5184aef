// Image output by file name: `.ppm` (any case) writes binary PPM, anything else PNG. The one
// place that decides which writer a path gets.
#pragma once

#include <string>

#include "image/image.h"

namespace vkrt {

enum class ImageFormat { Png, Ppm };

// The format written for `path`: Ppm for a name ending in .ppm (any case), else Png.
ImageFormat imageFormatFor(const std::string& path);

// True when `path` ends in .png or .ppm (any case): the names vkrt writes as their extension
// says. Any other name gets PNG bytes, and a warning.
bool hasImageExtension(const std::string& path);

// Writes `image` in the format of imageFormatFor(path), atomically. Throws IoError.
void writeImageAtomic(const Image& image, const std::string& path);

}  // namespace vkrt
