// The one place that maps a primitive reference (gpu_types.h: primRef, primKind, primIndex) to
// its shape, by the list of shapes (shape_list.h). Each shape's own file (triangle.h,
// sphere.h, ...) answers the queries; the rest of the host asks them here, by primRef. A shape
// that lacks one of the queries does not compile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "util/errors.h"
#include "gpu_types.h"
#include "scene/scene_desc.h"
#include "scene/shapes/ray_hit.h"
#include "scene/shapes/shape_list.h"

namespace vkrt::shapes {

// Kinds 0 .. kKinds - 1, in the order of shape_list.h, which is also the order in which the
// host lists primitives: every triangle, then every sphere, ...
#define VKRT_SHAPE_ONE(Type, member, name, kind, GpuType, binding) +1
inline constexpr std::uint32_t kKinds = 0 VKRT_SHAPES(VKRT_SHAPE_ONE);
#undef VKRT_SHAPE_ONE

// Each kind's name, singular and plural (for messages), by kind.
#define VKRT_SHAPE_NAME(Type, member, name, kind, GpuType, binding) std::string_view(name),
inline constexpr std::string_view kNames[] = {VKRT_SHAPES(VKRT_SHAPE_NAME)};
#undef VKRT_SHAPE_NAME
#define VKRT_SHAPE_PLURAL(Type, member, name, kind, GpuType, binding) std::string_view(#member),
inline constexpr std::string_view kPluralNames[] = {VKRT_SHAPES(VKRT_SHAPE_PLURAL)};
#undef VKRT_SHAPE_PLURAL

// The list's rows are in the order of their kinds.
#define VKRT_SHAPE_KIND(Type, member, name, kind, GpuType, binding) kind,
inline constexpr std::uint32_t kListedKinds[] = {VKRT_SHAPES(VKRT_SHAPE_KIND)};
#undef VKRT_SHAPE_KIND
static_assert([] {
  for (std::uint32_t k = 0; k < kKinds; ++k)
    if (kListedKinds[k] != k) return false;
  return true;
}(), "shape_list.h lists the shapes in the order of their kinds");

// How many primitives of `kind` the scene holds (0 for a kind that is no shape).
inline std::size_t count(const SceneDesc& scene, std::uint32_t kind) {
  switch (kind) {
#define VKRT_SHAPE_COUNT(Type, member, name, kind, GpuType, binding) \
  case kind: return scene.member.size();
    VKRT_SHAPES(VKRT_SHAPE_COUNT)
#undef VKRT_SHAPE_COUNT
    default: return 0;
  }
}

// f(shape) for the primitive that `ref` refers to.
template <class F>
decltype(auto) visit(const SceneDesc& scene, std::uint32_t ref, F&& f) {
  switch (gpu::primKind(ref)) {
#define VKRT_SHAPE_VISIT(Type, member, name, kind, GpuType, binding) \
  case kind: return f(scene.member[gpu::primIndex(ref)]);
    VKRT_SHAPES(VKRT_SHAPE_VISIT)
#undef VKRT_SHAPE_VISIT
  }
  throw InternalError("a primitive reference of no kind of shape");
}

// The queries, by primitive reference (each shape's file says what they mean for it).
inline void bounds(const SceneDesc& scene, std::uint32_t ref, dvec3& lo, dvec3& hi) {
  visit(scene, ref, [&](const auto& s) { bounds(s, lo, hi); });
}
inline bool neverHit(const SceneDesc& scene, std::uint32_t ref) {
  return visit(scene, ref, [](const auto& s) { return neverHit(s); });
}
// Whether some primitive can never be hit (the BVH leaves those out).
inline bool anyNeverHit(const SceneDesc& scene) {
  for (std::uint32_t kind = 0; kind < kKinds; ++kind)
    for (std::size_t i = 0; i < count(scene, kind); ++i)
      if (neverHit(scene, gpu::primRef(kind, static_cast<std::uint32_t>(i)))) return true;
  return false;
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
