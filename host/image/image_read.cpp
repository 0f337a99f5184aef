// Any image as bytes or as radiance, and the conversion between formats.
#include "image/image_read.h"

#include <algorithm>
#include <cmath>

#include "util/errors.h"
#include "image/encode.h"
#include "image/samples.h"
#include "platform/file_status.h"

namespace vkrt {

double recordedGamma(const ImageRecords& records) {
  std::optional<SampleRecord> record = sampleRecordOf(records);
  return record ? record->gamma : 1.0;
}

AnyImage readAnyImage(const std::string& path) {
  AnyImage image;
  // Only a regular file is looked into before it is read: the bytes of a FIFO can be read
  // once, and a read that waits on one must stay where a signal stops it (stb's).
  const bool regular = platform::isRegularFile(path);
  if (regular && isFloatImageFile(path)) {
    image.radiance = readFloatImage(path);
    return image;
  }
  image.bytes = readImage(path);
  // The records of its format (none for JPEG, which no row of the table reads).
  if (regular) image.bytes.text = readImageFileText(path);
  return image;
}

Image asBytes(const RadianceImage& image) { return encodeImage(image, recordedGamma(image.text)); }

RadianceImage asRadiance(const Image& bytes) {
  const double gamma = recordedGamma(bytes.text);
  float decoded[256];
  for (int b = 0; b < 256; ++b)
    decoded[b] = b == 0 ? 0.0f : b == 255 ? 1.0f : static_cast<float>(std::pow((b + 0.5) / 255.0, gamma));
  RadianceImage image(bytes.width, bytes.height);
  for (std::size_t i = 0; i < bytes.rgb.size(); ++i) image.rgb[i] = decoded[bytes.rgb[i]];
  image.text = bytes.text;
  return image;
}

Image readImageAsBytes(const std::string& path) {
  AnyImage image = readAnyImage(path);
  return image.radiance ? asBytes(*image.radiance) : std::move(image.bytes);
}

std::optional<LinearDifference> linearDifference(const RadianceImage& a, const RadianceImage& b) {
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) return std::nullopt;
  LinearDifference d;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double x = a.rgb[i], y = b.rgb[i];
    // The same value (two NaNs, the same infinity) differs by 0; a NaN or an infinity against
    // anything else, without bound.
    const bool same = x == y || (std::isnan(x) && std::isnan(y));
    double diff = same ? 0.0 : std::abs(x - y);
    if (std::isnan(diff)) diff = HUGE_VAL;
    d.maxDiff = std::max(d.maxDiff, diff);
    sum += diff * diff;
  }
  d.rmse = a.rgb.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.rgb.size()));
  return d;
}

void convertImage(const std::string& from, const std::string& to) {
  if (!hasImageExtension(to))
    throw UsageError("'" + to + "' is not named " + imageExtensionsText() + ": say which format to write");
  AnyImage image = readAnyImage(from);
  if (!image.radiance && !holdsLinearFloat(to)) {
    writeImageAtomic(image.bytes, to);
    return;
  }
  const RadianceImage radiance = image.radiance ? std::move(*image.radiance) : asRadiance(image.bytes);
  writeImageAtomic(radiance, to, recordedGamma(radiance.text));
}

}  // namespace vkrt
