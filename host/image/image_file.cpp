// The writer for a file name: PPM for .ppm, PNG otherwise.
#include "image/image_file.h"

#include <cctype>

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
  return extensionOf(path) == "ppm" ? ImageFormat::Ppm : ImageFormat::Png;
}

bool hasImageExtension(const std::string& path) {
  std::string ext = extensionOf(path);
  return ext == "png" || ext == "ppm";
}

void writeImageAtomic(const Image& image, const std::string& path) {
  if (imageFormatFor(path) == ImageFormat::Ppm)
    writePpmAtomic(image, path);
  else
    writePngAtomic(image, path);
}

}  // namespace vkrt
