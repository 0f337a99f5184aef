// The rays a render traced, by kind, and the samples that came out NaN or infinite: what
// every renderer reports (CPU and Vulkan, Whitted and path) and the render report carries.
#pragma once

#include <cstdint>

namespace vkrt {

struct RayCounts {
  std::uint64_t primary = 0, shadow = 0;
  std::uint64_t secondary = 0;   // mirror rays (the Whitted model) or scattered rays (the path integrators)
  // Pixels whose colour came out NaN or infinite (encoded as 0 or 1: image/encode.h); the
  // tests require 0 on every scene they render, and vkrt warns when it is not.
  std::uint64_t nonFinite = 0;
  // The Vulkan backend's BVH walk (traverse.glsl): the child boxes and the leaves' primitives
  // its rays tested (a shadow ray stops at its first hit); 0 where rays test every primitive,
  // and from the CPU backend, which does not count them.
  std::uint64_t boxTests = 0, primitiveTests = 0;
  std::uint64_t total() const { return primary + shadow + secondary; }
  RayCounts& operator+=(const RayCounts& o) {
    primary += o.primary;
    shadow += o.shadow;
    secondary += o.secondary;
    nonFinite += o.nonFinite;
    boxTests += o.boxTests;
    primitiveTests += o.primitiveTests;
    return *this;
  }
};

}  // namespace vkrt
