// How the compute shaders' workgroups are laid over a band of the image (raytrace.comp and
// pathtrace.comp share it): 8x8 tiles, visited in a scattered order. Vulkan-free.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace vkrt {

// A stride coprime with `n`, near n times the golden ratio's fraction, so that consecutive
// workgroups land on tiles far apart.
inline std::uint32_t scatterStride(std::uint32_t n) {
  if (n <= 2) return 1;
  std::uint32_t s = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(n * 0.6180339887));
  while (std::gcd(s, n) != 1) ++s;
  return s;
}

}  // namespace vkrt
