// The streamed writers: the sink over the path's format's RowWriter (image/image_file.h),
// on a temporary file renamed over the path when every row has come.
#include "image/row_sink.h"

#include "util/errors.h"
#include "image/encode.h"
#include "image/image_file.h"

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
  const ImageFormat& format = imageFormatFor(path);
  if (!format.linearFloat) {
    // An 8-bit format takes bytes: each band is encoded (gamma, 8 bits) as it comes.
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
  // Rows must come in order, each once (a writer may place rows, as PFM's does, but a band
  // missing would leave a hole).
  RowOrder order(width, height);
  writeRowsAtomic(path, format, width, height, records, [&](RowWriter& writer) {
    render([&](int y0, const RadianceImage& band) {
      order.take(y0, band.width, band.height);
      writer.radianceRows(y0, band);
    });
    order.complete();
  });
}

void writeBytesStreamed(const std::string& path, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const ByteRowSink&)>& render) {
  const ImageFormat& format = imageFormatFor(path);
  if (format.linearFloat) throw UsageError(bytesAsFloatMessage(path));
  // In order, each row once: a byte writer (an encoder) cannot seek back.
  RowOrder order(width, height);
  writeRowsAtomic(path, format, width, height, records, [&](RowWriter& writer) {
    render([&](int y0, const Image& band) {
      order.take(y0, band.width, band.height);
      writer.byteRows(y0, band);
    });
    order.complete();
  });
}

}  // namespace vkrt
