// Box-filtered shrinking of an 8-bit image.
#include "image/thumbnail.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace vkrt {

Image thumbnail(const Image& image, int maxWidth, int maxHeight) {
  if (image.width <= maxWidth && image.height <= maxHeight) {
    Image copy(image.width, image.height);
    copy.rgb = image.rgb;
    return copy;
  }
  const double f = std::min(static_cast<double>(maxWidth) / image.width, static_cast<double>(maxHeight) / image.height);
  const int w = std::max(1, static_cast<int>(image.width * f + 0.5)), h = std::max(1, static_cast<int>(image.height * f + 0.5));
  Image out(w, h);
  std::vector<std::uint64_t> sum(static_cast<std::size_t>(w) * 3);
  for (int ty = 0; ty < h; ++ty) {
    // Source rows [y0, y1) and columns [x0, x1) of each target pixel: at least one each.
    const int y0 = static_cast<int>(static_cast<long long>(ty) * image.height / h);
    const int y1 = std::max(y0 + 1, static_cast<int>(static_cast<long long>(ty + 1) * image.height / h));
    std::fill(sum.begin(), sum.end(), 0);
    for (int y = y0; y < y1; ++y) {
      const std::uint8_t* row = image.pixel(0, y);
      for (int tx = 0; tx < w; ++tx) {
        const int x0 = static_cast<int>(static_cast<long long>(tx) * image.width / w);
        const int x1 = std::max(x0 + 1, static_cast<int>(static_cast<long long>(tx + 1) * image.width / w));
        for (int x = x0; x < x1; ++x)
          for (int c = 0; c < 3; ++c) sum[tx * 3 + c] += row[x * 3 + c];
      }
    }
    for (int tx = 0; tx < w; ++tx) {
      const int x0 = static_cast<int>(static_cast<long long>(tx) * image.width / w);
      const int x1 = std::max(x0 + 1, static_cast<int>(static_cast<long long>(tx + 1) * image.width / w));
      const std::uint64_t n = static_cast<std::uint64_t>(x1 - x0) * (y1 - y0);
      for (int c = 0; c < 3; ++c) out.pixel(tx, ty)[c] = static_cast<std::uint8_t>((sum[tx * 3 + c] + n / 2) / n);
    }
  }
  return out;
}

}  // namespace vkrt
