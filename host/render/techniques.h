// The rendering techniques, one row each (techniques.cpp): which scenes it renders, and how
// each backend renders a batch of it. The backends (cpu_backend.cpp, vulkan_backend.cpp) ask
// techniqueFor and know no technique by name; a new technique is its shader of hooks
// (shaders/driver.glsl), its GPU host (gpu/), its CPU reference (cpu/) and its row here.
#pragma once

#include <functional>
#include <memory>

#include "image/radiance_image.h"
#include "render/backend.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "util/ray_counts.h"

namespace vkrt {

class Context;
struct VulkanTimings;

// A technique on the CPU backend: a batch rendered from the scene and its BVH.
using CpuTechnique =
    std::function<RadianceImage(const SceneDesc&, const Bvh&, const SampleBatch&, PixelProgress, RayCounts*)>;

// A technique on the Vulkan backend: its pipeline made ahead (from the scene's arrays before the
// BVH is built), and a batch rendered. It may keep what its batches share (the path
// integrators' upload of the scene): destroy it before the GpuScene it rendered.
struct VulkanTechnique {
  std::function<void(const Context&, const GpuScene& arrays, const SampleBatch& first, bool eachPrimitiveOnce)> prepare;
  std::function<RadianceImage(const Context&, const GpuScene&, const SampleBatch&, PixelProgress, RayCounts*,
                              VulkanTimings*)>
      render;
};

struct Technique {
  const char* name;
  bool (*renders)(const SceneDesc& scene);
  CpuTechnique (*cpu)(const BackendInputs& in);
  VulkanTechnique (*vulkan)(const BackendInputs& in);
};

// The row whose `renders` takes `scene` (the first; the last row takes every scene).
const Technique& techniqueFor(const SceneDesc& scene);

}  // namespace vkrt
