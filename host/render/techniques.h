// The rendering techniques, one row each (techniques.cpp): which scenes it renders, and how
// each backend renders a batch of it. The backends (cpu_backend.cpp, vulkan_backend.cpp) ask
// techniqueFor and know no technique by name; a new technique is its shader of hooks
// (shaders/driver.glsl), its CPU reference (cpu/) and its row here, whose Vulkan glue runs its
// shader on a GPU host (gpu/: the Whitted one for a view, or one of its own).
#pragma once

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

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
  // A view of the scene (vkrt --view NAME), with its --help line; null for the techniques a
  // scene chooses by its integrator.
  const char* view;
  // For a scene's own technique: the scenes it renders (the first row that takes a scene
  // renders it); null for a view, which only --view asks for.
  bool (*renders)(const SceneDesc& scene);
  // Batches of random samples, encoded with the scene's gamma; false: one deterministic sample
  // a pixel, gamma 1, streamed to the file where the output allows.
  bool sampled;
  CpuTechnique (*cpu)(const BackendInputs& in);
  VulkanTechnique (*vulkan)(const BackendInputs& in);
};

// The technique of a render: the view named `view` (a name viewNamed knows), or with none the
// scene's own.
const Technique& techniqueFor(const SceneDesc& scene, std::string_view view);

// The view named `name`, or null; and every view, in the table's order.
const Technique* viewNamed(std::string_view name);
std::vector<const Technique*> views();

}  // namespace vkrt
