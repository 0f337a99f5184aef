// A small copy of an 8-bit image, for pages that show many (the grading report's overview).
#pragma once

#include "image/image.h"

namespace vkrt {

// `image` shrunk to fit in maxWidth x maxHeight, keeping its shape (each side at least 1),
// each pixel the mean of the pixels it covers; an image that fits already is copied as it is.
Image thumbnail(const Image& image, int maxWidth, int maxHeight);

}  // namespace vkrt
