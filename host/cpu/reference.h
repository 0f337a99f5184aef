// CPU reference renderer: SceneDesc (+ its BVH) -> Image, in double precision, written
// plainly after SPEC sections 3-7. It is the tests' oracle for the GPU backend, so it shares
// no intersection or shading code with the shader.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "image/crop.h"
#include "image/image.h"
#include "scene/bvh.h"
#include "scene/scene_desc.h"

namespace vkrt {

struct RayCounts {
  std::uint64_t primary = 0, shadow = 0, reflection = 0;
  // Pixels whose colour came out NaN or infinite (written as 0 or 1: radianceToByte); the
  // tests require 0 on every scene they render, and vkrt warns when it is not.
  std::uint64_t nonFinite = 0;
  std::uint64_t total() const { return primary + shadow + reflection; }
};

struct CpuOptions {
  int threads = 0;   // 0: every hardware thread
  // Called after each finished tile with (pixels done, pixels total), from worker threads
  // (one at a time).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
  // Polled between tiles, from worker threads: true stops early (the image is then incomplete).
  std::function<bool()> stop;
  // Only these pixels of the scene's image (inside it), as an image of the crop's size; the
  // camera rays are the full image's (SPEC section 3).
  std::optional<PixelRect> crop;
};

Image renderReference(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options, RayCounts* counts);

}  // namespace vkrt
