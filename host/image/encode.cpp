// Radiance -> bytes, once, at output.
#include "image/encode.h"

#include <cmath>

namespace vkrt {

std::uint8_t encodeChannel(float c, double gamma) {
  if (!(c > 0.0f)) return 0;   // NaN, negative and zero
  float v = gamma == 1.0 ? c : static_cast<float>(std::pow(static_cast<double>(c), 1.0 / gamma));
  if (!(v < 1.0f)) return 255;
  return static_cast<std::uint8_t>(v * 255.0f);   // truncation is floor here: 0 < v < 1
}

void encodeRow(const float* in, std::size_t count, double gamma, std::uint8_t* out) {
  for (std::size_t i = 0; i < count; ++i) out[i] = encodeChannel(in[i], gamma);
}

Image encodeImage(const RadianceImage& image, double gamma) {
  Image out(image.width, image.height);
  const std::size_t n = image.rgb.size();
  for (std::size_t i = 0; i < n; ++i) out.rgb[i] = encodeChannel(image.rgb[i], gamma);
  out.text = image.text;
  return out;
}

}  // namespace vkrt
