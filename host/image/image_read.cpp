// Any image as bytes or as radiance, and the conversion between formats.
#include "image/image_read.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "image/encode.h"
#include "image/samples.h"

namespace vkrt {

double recordedGamma(const ImageRecords& records) {
  for (const auto& [keyword, text] : records)
    if (keyword == kSamplesKeyword)
      if (std::optional<SampleRecord> record = parseSampleRecord(text)) return record->gamma;
  return 1.0;
}

// Only a regular file is looked into before it is read: the bytes of a FIFO can be read once,
// and a read that waits on one must stay where a signal stops it (stb's).
bool readsAsRadiance(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && isFloatImageFile(path);
}

namespace {

// An 8-bit file with the records of its format (none for JPEG, which no row of the table reads).
Image readBytesWithRecords(const std::string& path) {
  Image image = readImage(path);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) image.text = readImageFileText(path);
  return image;
}

}  // namespace

Image readImageAsBytes(const std::string& path) {
  if (!readsAsRadiance(path)) return readBytesWithRecords(path);
  RadianceImage image = readFloatImage(path);
  return encodeImage(image, recordedGamma(image.text));
}

RadianceImage readImageAsRadiance(const std::string& path) {
  if (readsAsRadiance(path)) return readFloatImage(path);
  const Image bytes = readBytesWithRecords(path);
  const double gamma = recordedGamma(bytes.text);
  float decoded[256];
  for (int b = 0; b < 256; ++b)
    decoded[b] = b == 0 ? 0.0f : b == 255 ? 1.0f : static_cast<float>(std::pow((b + 0.5) / 255.0, gamma));
  RadianceImage image(bytes.width, bytes.height);
  for (std::size_t i = 0; i < bytes.rgb.size(); ++i) image.rgb[i] = decoded[bytes.rgb[i]];
  image.text = bytes.text;
  return image;
}

std::optional<LinearDifference> linearDifference(const RadianceImage& a, const RadianceImage& b) {
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size()) return std::nullopt;
  LinearDifference d;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double diff = std::abs(static_cast<double>(a.rgb[i]) - static_cast<double>(b.rgb[i]));
    d.maxDiff = std::max(d.maxDiff, diff);   // NaN (a NaN pixel) is left out here, and poisons the RMSE
    sum += diff * diff;
  }
  d.rmse = a.rgb.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.rgb.size()));
  return d;
}

void convertImage(const std::string& from, const std::string& to) {
  if (!hasImageExtension(to))
    throw UsageError("'" + to + "' is not named " + imageExtensionsText() + ": say which format to write");
  if (holdsLinearFloat(to) || readsAsRadiance(from)) {
    RadianceImage image = readImageAsRadiance(from);
    writeImageAtomic(image, to, recordedGamma(image.text));
  } else {
    writeImageAtomic(readBytesWithRecords(from), to);
  }
}

}  // namespace vkrt
