// Image comparison for tests and tools.
#include "compare/image_diff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

double ImageDiff::psnr() const {
  if (rmse == 0.0) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(255.0 / rmse);
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
  double squares = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* pa = a.pixel(x, y);
      const std::uint8_t* pb = b.pixel(x, y);
      int m = 0;
      for (int c = 0; c < 3; ++c) {
        int diff = std::abs(int(pa[c]) - int(pb[c]));
        sum += diff;
        squares += static_cast<double>(diff) * diff;
        m = std::max(m, diff);
      }
      if (m > 0) d.differing.push_back({x, y, m});
      d.maxChannelDiff = std::max(d.maxChannelDiff, m);
    }
  d.meanAbs = d.pixels ? static_cast<double>(sum) / (3.0 * static_cast<double>(d.pixels)) : 0.0;
  d.rmse = d.pixels ? std::sqrt(squares / (3.0 * static_cast<double>(d.pixels))) : 0.0;
  return d;
}

Image amplifiedDifference(const Image& a, const Image& b, int gain) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("image sizes differ");
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < out.rgb.size(); ++i)
    out.rgb[i] = static_cast<std::uint8_t>(std::min(255, std::abs(int(a.rgb[i]) - int(b.rgb[i])) * gain));
  return out;
}

namespace {

// The heatmap's colour for t in [0, 1]: blue, cyan, green, yellow, red.
std::array<std::uint8_t, 3> ramp(double t) {
  static const double stops[5][3] = {{0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  int i = std::min(3, static_cast<int>(t));
  double f = t - i;
  std::array<std::uint8_t, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = static_cast<std::uint8_t>(stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f);
  return c;
}

// 3x5 pixel digits and '/', for the legend's labels.
const char* glyph(char ch) {
  switch (ch) {
    case '0': return "111101101101111";
    case '1': return "010110010010111";
    case '2': return "111001111100111";
    case '3': return "111001111001111";
    case '4': return "101101111001001";
    case '5': return "111100111001111";
    case '6': return "111100111101111";
    case '7': return "111001001001001";
    case '8': return "111101111101111";
    case '9': return "111101111001111";
    case '/': return "001001010100100";
    default: return "000000000000000";
  }
}

void drawText(Image& img, int x, int y, const std::string& text, int scale) {
  for (char ch : text) {
    const char* g = glyph(ch);
    for (int gy = 0; gy < 5; ++gy)
      for (int gx = 0; gx < 3; ++gx)
        if (g[gy * 3 + gx] == '1')
          for (int sy = 0; sy < scale; ++sy)
            for (int sx = 0; sx < scale; ++sx) {
              int px = x + gx * scale + sx, py = y + gy * scale + sy;
              if (px >= 0 && px < img.width && py >= 0 && py < img.height) std::fill_n(img.pixel(px, py), 3, 255);
            }
    x += 4 * scale;
  }
}

}  // namespace

Image differenceHeatmap(const ImageDiff& diff, int scaleSteps) {
  scaleSteps = std::max(1, scaleSteps);
  const int scale = diff.width >= 240 ? 2 : 1;   // label size
  const int legend = 12 * scale;
  Image out(diff.width, diff.height + legend);
  for (const PixelDiff& d : diff.differing) {
    auto c = ramp(static_cast<double>(d.maxChannelDiff - 1) / std::max(1, scaleSteps - 1));
    std::copy(c.begin(), c.end(), out.pixel(d.x, d.y));
  }
  // The legend: the ramp from 1 step (left) to the scale (right), labelled at both ends.
  const int barTop = diff.height + 2 * scale, barHeight = 3 * scale;
  for (int x = 0; x < out.width; ++x) {
    auto c = ramp(out.width > 1 ? static_cast<double>(x) / (out.width - 1) : 1.0);
    for (int y = barTop; y < barTop + barHeight && y < out.height; ++y) std::copy(c.begin(), c.end(), out.pixel(x, y));
  }
  drawText(out, 1, barTop + barHeight + scale, "1/255", scale);
  std::string label = std::to_string(scaleSteps) + "/255";
  drawText(out, out.width - static_cast<int>(label.size()) * 4 * scale, barTop + barHeight + scale, label, scale);
  return out;
}

}  // namespace vkrt
