// PNG files: the streamed writer, atomic writing (temporary file + rename), and reading the
// records. The default format of image/image_file.cpp's table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "util/errors.h"
#include "image/atomic_file.h"   // checkOutputWritable
#include "image/byte_sink.h"
#include "image/image.h"
#include "image/image_file.h"   // RowWriter; readImage, which reads PNG
#include "image/radiance_image.h"

namespace vkrt {

// A PNG written into `sink` row by row, top first: the header and the records (tEXt
// chunks) at construction, each row (width * 3 bytes) filtered and deflated as it comes, the
// end at finish(). Memory: a few rows and zlib's state. Throws IoError, OutOfMemory,
// Interrupted (polled per row), InternalError for more or fewer rows than `height`.
class PngRowEncoder : public RowWriter {
 public:
  PngRowEncoder(ByteSink& sink, int width, int height,
                const std::vector<std::pair<std::string, std::string>>& records, const std::string& path);
  ~PngRowEncoder() override;
  PngRowEncoder(const PngRowEncoder&) = delete;
  PngRowEncoder& operator=(const PngRowEncoder&) = delete;
  void row(const std::uint8_t* rgb);
  // Each row of `band` through row(); y0 is not checked here (the rows must follow on).
  void byteRows(int y0, const Image& band) override;
  void finish() override;

 private:
  struct State;
  void pump(int flush);
  ByteSink& sink_;
  int height_, rows_ = 0;
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

// The PNG file of a render (each row encoded with `gamma`) for `vkrt view`'s page, made in
// memory (a MemorySink): the bytes writePngAtomic writes for the image without its records.
// Throws IoError, OutOfMemory, Interrupted.
std::string pngBytes(const RadianceImage& image, double gamma);

// The table's functions (image/image_file.h, ImageFormat): a PngRowEncoder; whether the file
// starts with the PNG signature; its tEXt chunks, read without decoding the image. readPngText
// throws IoError for a file that cannot be read or ends before its IEND chunk.
std::unique_ptr<RowWriter> openPngRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path);
bool isPngFile(const std::string& path);
// Throws IoError (imageReadError) when the PNG at `path` inflates to more bytes than its
// header's pixels take (a row's filter byte and bytes, Adam7's passes allowed for): a decoder
// would hold them all, and stb_image grows its buffer up to 2 GB for a 64x48 image with 2 GB of
// zeros compressed behind it. Inflates into a small buffer, stopping past the bound; a file that
// is not a PNG, or whose data is damaged, is left to the decoder to say so.
void checkPngInflatesToItsPixels(const std::string& path);
ImageRecords readPngText(const std::string& path);

}  // namespace vkrt
