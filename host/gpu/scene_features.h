// The specialization constants both compute shaders give the same meaning (kSpecHas*,
// gpu_render.h): what a scene uses, so that the driver compiles out the code of what it
// lacks. The host side of shaders/scene_features.glsl; each renderer adds its shader's own
// (vulkan_renderer.cpp, vulkan_path_renderer.cpp).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "scene/flatten.h"

namespace vkrt {

// Sets the shared constants of `spec` (indexed by constant id, bools as 0/1) to what `scene`
// uses: triangles, spheres, smooth normals, point and directional lights, attenuation.
void setSharedFeatures(const GpuScene& scene, std::vector<std::uint32_t>& spec);

// A feature's constant and its name in --stats ("left out: spheres, attenuation").
struct FeatureName {
  std::uint32_t id;
  const char* name;
};

// The names of the shared features, then of `own`, whose constants are 0 in `spec`, joined
// by ", " ("" when nothing is left out).
std::string leftOutNames(const std::vector<std::uint32_t>& spec, std::initializer_list<FeatureName> own);

}  // namespace vkrt
