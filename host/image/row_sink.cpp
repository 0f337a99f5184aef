// The streamed writers: one RowSink per format over an open temporary file.
#include "image/row_sink.h"

#include <cstdint>

#include "errors.h"
#include "image/atomic_file.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"
#include "interrupt.h"

namespace vkrt {

namespace {

// Checks that bands come in order, each row once, and that all came.
class RowOrder {
 public:
  RowOrder(int width, int height) : width_(width), height_(height) {}
  void take(int y0, int bandWidth, int bandHeight) {
    if (y0 != next_ || bandWidth != width_ || bandHeight > height_ - y0)
      throw InternalError("streamed image: rows " + std::to_string(y0) + "+" + std::to_string(bandHeight) +
                          " after " + std::to_string(next_) + " of a " + std::to_string(width_) + "x" +
                          std::to_string(height_) + " image");
    next_ = y0 + bandHeight;
  }
  void complete() const {
    if (next_ != height_)
      throw InternalError("streamed image: " + std::to_string(next_) + " rows of " + std::to_string(height_));
  }

 private:
  int width_, height_, next_ = 0;
};

}  // namespace

void writeImageStreamed(const std::string& path, double gamma, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const RowSink&)>& render) {
  if (imageFormatFor(path) != ImageFormat::Pfm) {
    // PNG and PPM take bytes: each band is encoded (gamma, 8 bits) as it comes.
    writeBytesStreamed(path, width, height, records, [&](const ByteRowSink& bytes) {
      Image encoded;
      render([&](int y0, const RadianceImage& band) {
        encoded.width = band.width, encoded.height = band.height;
        encoded.rgb.resize(band.rgb.size());
        encodeRow(band.rgb.data(), band.rgb.size(), gamma, encoded.rgb.data());
        bytes(y0, encoded);
      });
    });
    return;
  }
  // Rows must come in order, each once (the byte encoders cannot seek back; the PFM writer
  // places rows, but a band missing would leave a hole).
  RowOrder order(width, height);
  writeFileAtomic(path, ".pfm.tmp", [&](int fd) {
    PfmRowWriter pfm(fd, width, height, records, path);
    render([&](int y0, const RadianceImage& band) {
      order.take(y0, band.width, band.height);
      pfm.rows(y0, band);
    });
    order.complete();
    pfm.finish();
  });
}

void writeBytesStreamed(const std::string& path, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const ByteRowSink&)>& render) {
  RowOrder order(width, height);
  switch (imageFormatFor(path)) {
    case ImageFormat::Pfm:
      throw UsageError("'" + path + "': a .pfm holds linear radiance, and this image is 8-bit; write .png or .ppm");
    case ImageFormat::Png:
      writeFileAtomic(path, ".png.tmp", [&](int fd) {
        PngRowEncoder png(fd, width, height, records, path);
        render([&](int y0, const Image& band) {
          order.take(y0, band.width, band.height);
          for (int y = 0; y < band.height; ++y) png.row(band.pixel(0, y));
        });
        order.complete();
        png.finish();
      });
      break;
    case ImageFormat::Ppm:
      writeFileAtomic(path, ".ppm.tmp", [&](int fd) {
        writePpmHeader(fd, width, height, records, path);
        render([&](int y0, const Image& band) {
          order.take(y0, band.width, band.height);
          throwIfInterrupted();
          writeAll(fd, band.rgb.data(), band.rgb.size(), path);
        });
        order.complete();
      });
      break;
  }
}

}  // namespace vkrt
