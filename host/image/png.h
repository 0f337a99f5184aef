// PNG files: atomic writing (temporary file + rename) and reading (for tests and diffs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "image/atomic_file.h"   // checkOutputWritable
#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// A PNG written into an open file row by row, top first: the header and the records (tEXt
// chunks) at construction, each row (width * 3 bytes) filtered and deflated as it comes, the
// end at finish(). Memory: a few rows and zlib's state. Throws IoError, OutOfMemory,
// Interrupted (polled per row), InternalError for more or fewer rows than `height`.
class PngRowEncoder {
 public:
  PngRowEncoder(int fd, int width, int height, const std::vector<std::pair<std::string, std::string>>& records,
                const std::string& path);
  ~PngRowEncoder();
  PngRowEncoder(const PngRowEncoder&) = delete;
  PngRowEncoder& operator=(const PngRowEncoder&) = delete;
  void row(const std::uint8_t* rgb);
  void finish();

 private:
  struct State;
  void pump(int flush);
  int fd_, height_, rows_ = 0;
  std::size_t rowBytes_;
  std::string path_;
  std::unique_ptr<State> state_;
};

// Writes `image` to a temporary file beside `path` and renames it over `path`, so an existing
// file is replaced whole or not at all. Throws IoError; no temporary file is left behind.
void writePngAtomic(const Image& image, const std::string& path);

// The same for a render, each row encoded with `gamma` (image/encode.h) as it is written: no
// 8-bit copy of the image is made.
void writePngAtomic(const RadianceImage& image, double gamma, const std::string& path);

// Reads a PNG, a binary PPM (P6) or a JPEG as 8-bit RGB. Throws IoError.
Image readImage(const std::string& path);

// The width and height readImage would give, from the file's header, without decoding its
// pixels. Throws IoError for a file readImage cannot read.
void readImageSize(const std::string& path, int& width, int& height);

}  // namespace vkrt
