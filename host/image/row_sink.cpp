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

namespace vkrt {

void writeImageStreamed(const std::string& path, double gamma, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const RowSink&)>& render) {
  const std::size_t rowChannels = static_cast<std::size_t>(width) * 3;
  // Rows must come in order, each once: the PNG and PPM encoders cannot seek back.
  int next = 0;
  auto inOrder = [&](int y0, const RadianceImage& band) {
    if (y0 != next || band.width != width || band.height > height - y0)
      throw InternalError("writeImageStreamed: rows " + std::to_string(y0) + "+" + std::to_string(band.height) +
                          " after " + std::to_string(next) + " of a " + std::to_string(width) + "x" +
                          std::to_string(height) + " image");
    next = y0 + band.height;
  };
  auto complete = [&] {
    if (next != height)
      throw InternalError("writeImageStreamed: " + std::to_string(next) + " rows of " + std::to_string(height));
  };
  switch (imageFormatFor(path)) {
    case ImageFormat::Png:
      writeFileAtomic(path, ".png.tmp", [&](int fd) {
        PngRowEncoder png(fd, width, height, records, path);
        std::vector<std::uint8_t> bytes(rowChannels);
        render([&](int y0, const RadianceImage& band) {
          inOrder(y0, band);
          for (int y = 0; y < band.height; ++y) {
            encodeRow(band.pixel(0, y), rowChannels, gamma, bytes.data());
            png.row(bytes.data());
          }
        });
        complete();
        png.finish();
      });
      break;
    case ImageFormat::Ppm:
      writeFileAtomic(path, ".ppm.tmp", [&](int fd) {
        writePpmHeader(fd, width, height, records, path);
        std::vector<std::uint8_t> bytes;
        render([&](int y0, const RadianceImage& band) {
          inOrder(y0, band);
          bytes.resize(rowChannels * static_cast<std::size_t>(band.height));
          encodeRow(band.rgb.data(), bytes.size(), gamma, bytes.data());
          writeAll(fd, bytes.data(), bytes.size(), path);
        });
        complete();
      });
      break;
    case ImageFormat::Pfm:
      writeFileAtomic(path, ".pfm.tmp", [&](int fd) {
        PfmRowWriter pfm(fd, width, height, records, path);
        render([&](int y0, const RadianceImage& band) {
          inOrder(y0, band);
          pfm.rows(y0, band);
        });
        complete();
        pfm.finish();
      });
      break;
  }
}

}  // namespace vkrt
