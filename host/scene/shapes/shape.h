// The one place that maps a primitive reference (gpu_types.h: primRef, primKind, primIndex) to
// its shape. Each shape's own file (triangle.h, sphere.h) answers the queries; the rest of the
// host asks them here, by primRef. A new shape adds its file, its line in count() and its line
// in visit(); a shape that lacks one of the queries does not compile.
#pragma once

#include <cstddef>
#include <cstdint>

#include "gpu_types.h"
#include "scene/scene_desc.h"
#include "scene/shapes/ray_hit.h"
#include "scene/shapes/sphere.h"
#include "scene/shapes/triangle.h"

namespace vkrt::shapes {

// Kinds 0 .. kKinds - 1 (gpu_types.h: kPrimTriangle, kPrimSphere), in the order in which the
// host lists primitives: every triangle, then every sphere.
inline constexpr std::uint32_t kKinds = 2;

// How many primitives of `kind` the scene holds.
inline std::size_t count(const SceneDesc& scene, std::uint32_t kind) {
  switch (kind) {
    case gpu::kPrimTriangle: return scene.triangles.size();
    case gpu::kPrimSphere: return scene.spheres.size();
    default: return 0;
  }
}

// f(shape) for the primitive that `ref` refers to.
template <class F>
decltype(auto) visit(const SceneDesc& scene, std::uint32_t ref, F&& f) {
  switch (gpu::primKind(ref)) {
    case gpu::kPrimSphere: return f(scene.spheres[gpu::primIndex(ref)]);
    default: return f(scene.triangles[gpu::primIndex(ref)]);
  }
}

// The queries, by primitive reference (each shape's file says what they mean for it).
inline void bounds(const SceneDesc& scene, std::uint32_t ref, dvec3& lo, dvec3& hi) {
  visit(scene, ref, [&](const auto& s) { bounds(s, lo, hi); });
}
inline bool neverHit(const SceneDesc& scene, std::uint32_t ref) {
  return visit(scene, ref, [](const auto& s) { return neverHit(s); });
}
inline double area(const SceneDesc& scene, std::uint32_t ref) {
  return visit(scene, ref, [](const auto& s) { return area(s); });
}
inline std::uint32_t material(const SceneDesc& scene, std::uint32_t ref) {
  return visit(scene, ref, [](const auto& s) { return s.material; });
}
// Sets hit.t (and what the shape records of the hit); hit.prim is left alone.
inline bool intersect(const SceneDesc& scene, std::uint32_t ref, const Ray& ray, double tMin, double tMax, Hit& hit) {
  return visit(scene, ref, [&](const auto& s) { return intersect(s, ray, tMin, tMax, hit); });
}
inline dvec3 normalAt(const SceneDesc& scene, const Hit& hit, const dvec3& p) {
  return visit(scene, hit.prim, [&](const auto& s) { return normalAt(s, hit, p); });
}
inline SurfacePoint samplePoint(const SceneDesc& scene, std::uint32_t ref, double u, double v) {
  return visit(scene, ref, [&](const auto& s) { return samplePoint(s, u, v); });
}
inline SurfacePoint densityAt(const SceneDesc& scene, std::uint32_t ref, const dvec3& p) {
  return visit(scene, ref, [&](const auto& s) { return densityAt(s, p); });
}
inline bool within(const SceneDesc& scene, std::uint32_t ref, const dvec3& p, double reach) {
  return visit(scene, ref, [&](const auto& s) { return within(s, p, reach); });
}

}  // namespace vkrt::shapes
