// Image comparison for tests and tools.
#include "image/compare.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace vkrt {

long long ImageDiff::countOver(int steps) const {
  return std::count_if(differing.begin(), differing.end(),
                       [&](const PixelDiff& d) { return d.maxChannelDiff > steps; });
}

std::string ImageDiff::worst(int n) const {
  std::vector<PixelDiff> sorted = differing;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const PixelDiff& a, const PixelDiff& b) { return a.maxChannelDiff > b.maxChannelDiff; });
  std::string s;
  for (int i = 0; i < n && i < static_cast<int>(sorted.size()); ++i)
    s += "(" + std::to_string(sorted[i].x) + "," + std::to_string(sorted[i].y) + ") " +
         std::to_string(sorted[i].maxChannelDiff) + "/255  ";
  return s.empty() ? "no differing pixels" : s;
}

ImageDiff compare(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
  ImageDiff d;
  d.width = a.width;
  d.height = a.height;
  d.pixels = static_cast<long long>(a.width) * a.height;
  long long sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* pa = a.pixel(x, y);
      const std::uint8_t* pb = b.pixel(x, y);
      int m = 0;
      for (int c = 0; c < 3; ++c) {
        int diff = std::abs(int(pa[c]) - int(pb[c]));
        sum += diff;
        m = std::max(m, diff);
      }
      if (m > 0) d.differing.push_back({x, y, m});
      d.maxChannelDiff = std::max(d.maxChannelDiff, m);
    }
  d.meanAbs = d.pixels ? static_cast<double>(sum) / (3.0 * static_cast<double>(d.pixels)) : 0.0;
  return d;
}

Image amplifiedDifference(const Image& a, const Image& b, int gain) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("image sizes differ");
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < out.rgb.size(); ++i)
    out.rgb[i] = static_cast<std::uint8_t>(std::min(255, std::abs(int(a.rgb[i]) - int(b.rgb[i])) * gain));
  return out;
}

}  // namespace vkrt
