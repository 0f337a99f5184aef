// Image files by format: `.pfm` (any case) writes a Portable Float Map (linear,
// unquantized), `.ppm` binary PPM, anything else PNG; and linear-float files are read here.
// The one place that decides which writer a path gets and which reader a float file needs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

enum class ImageFormat { Png, Ppm, Pfm };

// The format written for `path`: Pfm for a name ending in .pfm, Ppm for .ppm (any case),
// else Png.
ImageFormat imageFormatFor(const std::string& path);

// True when `path` ends in .png, .ppm or .pfm (any case): the names vkrt writes as their extension
// says. Any other name gets PNG bytes, and a warning.
bool hasImageExtension(const std::string& path);

// Writes `image` in the format of imageFormatFor(path), atomically. Throws IoError, and
// UsageError for a .pfm name (bytes are no linear radiance: PFM is written from a
// RadianceImage).
void writeImageAtomic(const Image& image, const std::string& path);

// Linear-float image files (today PFM), read by what gathers float tiles and sample batches
// (merge.cpp) and their records (crop.cpp), which ask these rather than a format by name.
// Whether the file at `path` is one (by its first bytes, whatever its name).
bool isFloatImageFile(const std::string& path);
// Reads one whole (its records into `text`; `samples` left at 1), or only its size and
// records after checking that its pixels are all there. Throws IoError.
RadianceImage readFloatImage(const std::string& path);
RadianceImage readFloatImageInfo(const std::string& path);
// Its records. Throws IoError.
std::vector<std::pair<std::string, std::string>> readFloatImageText(const std::string& path);

// Writes a render: .pfm as it is (linear float, with its records), .png and .ppm encoded with
// `gamma` (image/encode.h). Throws IoError.
void writeImageAtomic(const RadianceImage& image, const std::string& path, double gamma);

}  // namespace vkrt
