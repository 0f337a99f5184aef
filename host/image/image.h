// An 8-bit RGB image, row 0 at the top, and the one conversion from radiance to bytes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vkrt {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;   // width * height * 3 bytes
  // (keyword, text) records written with the image: PNG tEXt chunks, PPM header comments
  // "# KEYWORD TEXT". Keywords: 1-79 printable Latin-1 characters, no spaces; texts one line.
  std::vector<std::pair<std::string, std::string>> text;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
  std::uint8_t* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
};

// doc/scene-format.md, "Conventions": floor(clamp(c, 0, 1) * 255), not rounding. NaN becomes 0.
inline std::uint8_t radianceToByte(double c) {
  if (!(c > 0.0)) return 0;
  return static_cast<std::uint8_t>(std::floor(std::min(c, 1.0) * 255.0));
}

}  // namespace vkrt
