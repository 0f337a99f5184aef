// OpenEXR files: a RadianceImage written as 32-bit float R, G, B channels (linear,
// unquantized, scanlines top to bottom, ZIP-compressed), through Debian's OpenEXR library, and
// read back. The image's records (RadianceImage::text: a crop's place, a batch's samples, the
// render's identity) are string attributes of the header, each named by its keyword, so that
// other EXR tools keep and show them. Knows nothing of rendering.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/byte_sink.h"
#include "image/image_file.h"
#include "image/radiance_image.h"

namespace vkrt {

// An EXR written into `sink` as its rows come, in order from the top: the header at
// construction, each band's rows as they come, the line offsets at finish(). Memory: what
// OpenEXR buffers of one band. Throws IoError, Interrupted, InternalError for rows out of order.
class ExrRowWriter : public RowWriter {
 public:
  ExrRowWriter(ByteSink& sink, int width, int height, const ImageRecords& records, const std::string& path);
  ~ExrRowWriter() override;
  // Rows [y0, y0 + band.height) of the image (band.width == width), after those before them.
  void radianceRows(int y0, const RadianceImage& band) override;
  void finish() override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// An ExrRowWriter, as the table's openRows (image/image_file.h, ImageFormat).
std::unique_ptr<RowWriter> openExrRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path);

// Reads an EXR's R, G and B channels as float (a missing channel is 0; a file with only Y, a
// grey image, gives Y in all three), over its data window, and its string attributes whose
// names start with "vkrt-" into `text`. `samples` is left at 1 (the caller reads it from a
// record). Throws IoError for a file that cannot be read or is no EXR.
RadianceImage readExr(const std::string& path);

// Its size and records, without its pixels (`rgb` stays empty). Throws IoError.
RadianceImage readExrInfo(const std::string& path);

// Its records. Throws IoError.
ImageRecords readExrText(const std::string& path);

// True when the file starts with the EXR magic number.
bool isExrFile(const std::string& path);

}  // namespace vkrt
