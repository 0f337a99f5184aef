// PPM writing: the header, then the image's rows as they are in memory (Image is already
// 8-bit RGB, top row first, as P6 wants), a band of rows per write() so that a Ctrl-C is
// seen during a large image.
#include "image/ppm.h"

#include <algorithm>

#include "image/atomic_file.h"
#include "interrupt.h"

namespace vkrt {

void writePpmHeader(int fd, int width, int height, const std::vector<std::pair<std::string, std::string>>& records,
                    const std::string& path) {
  std::string header = "P6\n";
  for (const auto& [keyword, value] : records) header += "# " + keyword + " " + value + "\n";
  header += std::to_string(width) + " " + std::to_string(height) + "\n255\n";
  writeAll(fd, reinterpret_cast<const std::uint8_t*>(header.data()), header.size(), path);
}

void writePpmAtomic(const Image& image, const std::string& path) {
  writeFileAtomic(path, ".ppm.tmp", [&](int fd) {
    writePpmHeader(fd, image.width, image.height, image.text, path);
    constexpr int kRowsPerWrite = 64;
    for (int y = 0; y < image.height; y += kRowsPerWrite) {
      throwIfInterrupted();
      int rows = std::min(kRowsPerWrite, image.height - y);
      writeAll(fd, image.pixel(0, y), static_cast<std::size_t>(rows) * static_cast<std::size_t>(image.width) * 3,
               path);
    }
  });
}

}  // namespace vkrt
