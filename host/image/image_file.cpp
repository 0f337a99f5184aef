// The writer for a file name (PFM for .pfm, PPM for .ppm, PNG otherwise), and the reader of a
// linear-float file.
#include "image/image_file.h"

#include <cctype>

#include "errors.h"
#include "image/encode.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"

namespace vkrt {
namespace {

// The extension of the last path component, lower-cased, without the dot ("" when none).
std::string extensionOf(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::size_t start = slash == std::string::npos ? 0 : slash + 1;
  std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || dot < start) return {};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

ImageFormat imageFormatFor(const std::string& path) {
  std::string ext = extensionOf(path);
  return ext == "pfm" ? ImageFormat::Pfm : ext == "ppm" ? ImageFormat::Ppm : ImageFormat::Png;
}

bool hasImageExtension(const std::string& path) {
  std::string ext = extensionOf(path);
  return ext == "png" || ext == "ppm" || ext == "pfm";
}

void writeImageAtomic(const Image& image, const std::string& path) {
  if (imageFormatFor(path) == ImageFormat::Pfm)
    throw UsageError("'" + path + "': a .pfm holds linear radiance, and this image is 8-bit; write .png or .ppm");
  if (imageFormatFor(path) == ImageFormat::Ppm)
    writePpmAtomic(image, path);
  else
    writePngAtomic(image, path);
}

void writeImageAtomic(const RadianceImage& image, const std::string& path, double gamma) {
  switch (imageFormatFor(path)) {
    case ImageFormat::Pfm: writePfmAtomic(image, path); break;
    case ImageFormat::Ppm: writePpmAtomic(encodeImage(image, gamma), path); break;
    case ImageFormat::Png: writePngAtomic(image, gamma, path); break;   // encoded row by row
  }
}

bool isFloatImageFile(const std::string& path) { return isPfmFile(path); }

RadianceImage readFloatImage(const std::string& path) { return readPfm(path); }

RadianceImage readFloatImageInfo(const std::string& path) { return readPfmInfo(path); }

std::vector<std::pair<std::string, std::string>> readFloatImageText(const std::string& path) {
  return readPfmText(path);
}

}  // namespace vkrt
