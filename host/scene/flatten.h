// SceneDesc -> GpuScene: the arrays the GPU reads, in the layouts of gpu_types.h (float32).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "gpu_types.h"
#include "scene/bvh.h"
#include "scene/scene_desc.h"

namespace vkrt {

struct GpuScene {
  std::uint32_t width = 0, height = 0, maxDepth = 0;
  // The float32 frame (ray_offset.h): world point x is (x - origin) * scale in every position
  // below; lengths are multiplied by scale (a power of two), directions are as they are.
  dvec3 origin{0.0};
  double scale = 1.0;
  gpu::GpuCamera camera{};   // doc/scene-format.md, "Camera"
  gpu::GpuCutoff cutoff{};   // the Whitted shader's exactness cut-off (gpu_types.h)
  // Each shape's primitives in its GPU layout (shapes/shape_list.h), at the SceneDesc's indices.
#define VKRT_SHAPE_MEMBER(Type, member, name, kind, GpuType, binding) std::vector<GpuType> member;
  VKRT_SHAPES(VKRT_SHAPE_MEMBER)
#undef VKRT_SHAPE_MEMBER
  std::vector<gpu::GpuTriangleNormals> triangleNormals;   // only for `trinormal` triangles
  std::vector<gpu::GpuLight> lights;
  std::vector<gpu::GpuMaterial> materials;   // w fields: BRDF model, roughness, shininess, quad light
  std::vector<gpu::GpuQuadLight> quadLights;   // scene-centred, as every other position
  // The emissive triangles and spheres that next-event estimation samples (scene/emitters.h);
  // path.emitterCount and path.emitterWeightScale go with them.
  std::vector<gpu::GpuEmitter> emitters;
  // The path integrators' settings and camera (gpu_types.h); the renderer adds the seed, the
  // sample range and the camera rule. Meaningless for Integrator::Raytracer.
  gpu::GpuPathParams path{};
  std::uint32_t spp = 1;   // the scene's `spp`
  Bvh bvh;
};

// Converts to float32 layouts and builds the BVH. `arraysMade`, when given, is called on
// another thread once every member but `bvh` is made, while the BVH may still be building:
// it may read every member but `bvh`, and flatten returns when it has returned (the Vulkan
// backend makes its pipeline there).
GpuScene flatten(const SceneDesc& scene, const std::function<void(const GpuScene&)>& arraysMade = {});

// The settings of doc/path-tracing.md, "Commands" in the shader's terms, and the camera
// (flatten's GpuScene::path; the render checks the shader's limits with it before flattening).
gpu::GpuPathParams pathParams(const SceneDesc& scene, const gpu::GpuCamera& camera = {});

// How many primitives the scene holds, of every kind.
inline std::size_t primitiveCount(const GpuScene& scene) {
  std::size_t n = 0;
#define VKRT_SHAPE_COUNT(Type, member, name, kind, GpuType, binding) n += scene.member.size();
  VKRT_SHAPES(VKRT_SHAPE_COUNT)
#undef VKRT_SHAPE_COUNT
  return n;
}

}  // namespace vkrt
