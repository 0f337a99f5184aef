// A linear float RGB image: what both renderers return (Whitted and path integrators alike).
// Quantization to bytes and the `gamma` encoding happen once, at output (image/encode);
// `.pfm` writes it as it is. Row 0 at the top.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vkrt {

struct RadianceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;          // width * height * 3 floats: radiance, the mean of `samples`
  std::uint64_t samples = 1;       // samples per pixel averaged into rgb (1 for the Whitted model)
  // (keyword, text) records written with the image, as Image::text.
  std::vector<std::pair<std::string, std::string>> text;

  RadianceImage() = default;
  RadianceImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}
  float* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  const float* pixel(int x, int y) const { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
};

}  // namespace vkrt
