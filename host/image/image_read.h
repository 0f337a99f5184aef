// Any image vkrt reads (every format of the table in image_file.h, and JPEG), as what a
// comparison or a conversion needs: 8-bit RGB as vkrt would have written it, or linear
// radiance. The gamma between the two is the one the image's records say it was rendered for
// (`vkrt-samples`, image/samples.h), else 1 (the Whitted model's, and any image vkrt did not
// write). Knows nothing of rendering.
#pragma once

#include <optional>
#include <string>

#include "image/image.h"
#include "image/image_file.h"
#include "image/radiance_image.h"

namespace vkrt {

// The gamma of `records`' vkrt-samples record, else 1.
double recordedGamma(const ImageRecords& records);

// The file as it is, with its records: a linear-float file as radiance, any other (PNG, PPM,
// JPEG) as 8-bit RGB in `bytes`. Only a regular file is looked into for its format: anything
// else (a FIFO, whose bytes can be read once) is read as 8-bit. Throws IoError.
struct AnyImage {
  std::optional<RadianceImage> radiance;   // set for a linear-float file (then `bytes` is empty)
  Image bytes;
};
AnyImage readAnyImage(const std::string& path);

// A linear-float image as 8-bit RGB with its records, encoded with its recorded gamma
// (image/encode.h): the bytes vkrt writes for it as a PNG.
Image asBytes(const RadianceImage& image);

// An 8-bit image as linear radiance with its records, decoded with its recorded gamma g: each
// byte b as the middle of what encodes to it, ((b + 0.5) / 255)^g, and 0 and 255 as 0 and 1,
// so that encoded again with g every byte comes back.
RadianceImage asRadiance(const Image& bytes);

// readAnyImage, as 8-bit (asBytes for a float file). Throws IoError.
Image readImageAsBytes(const std::string& path);

// What two linear-float images differ by, in their own (radiance) units: the largest channel
// difference and the root mean square over all channels; nothing when their sizes differ.
// Channels of the same value (two NaNs, the same infinity) differ by 0; a NaN or an infinity
// against any other value, by infinity.
struct LinearDifference {
  double maxDiff = 0.0, rmse = 0.0;
};
std::optional<LinearDifference> linearDifference(const RadianceImage& a, const RadianceImage& b);

// Writes the image at `from` as the format of `to`'s name (image_file.h), with its records:
// float to float as it is, float to 8-bit encoded with the recorded gamma, 8-bit to float
// decoded with it, 8-bit to 8-bit as it is. Throws IoError, and UsageError for a name of no
// format (written as nothing: the caller checks names first).
void convertImage(const std::string& from, const std::string& to);

}  // namespace vkrt
