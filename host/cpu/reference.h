// CPU reference renderer: SceneDesc (+ its BVH) -> Image, in double precision, written
// plainly after SPEC sections 3-7. It is the tests' oracle for the GPU backend, so it shares
// no intersection or shading code with the shader.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "image/image.h"
#include "scene/bvh.h"
#include "scene/scene_desc.h"

namespace vkrt {

struct RayCounts {
  std::uint64_t primary = 0, shadow = 0, reflection = 0;
  std::uint64_t total() const { return primary + shadow + reflection; }
};

struct CpuOptions {
  int threads = 0;   // 0: every hardware thread
  // Called after each finished tile with (pixels done, pixels total), from worker threads
  // (one at a time).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
  // Set to true from elsewhere to stop early (the image is then incomplete).
  const std::atomic<bool>* cancel = nullptr;
};

Image renderReference(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options, RayCounts* counts);

}  // namespace vkrt
