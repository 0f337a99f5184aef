// The secondary-ray offset policy: how far a shadow or mirror ray leaving a primitive ignores
// hits. The policy is stated once, in gpu_limits.h; both backends take their
// numbers from here. Depends on the scene description only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gpu_types.h"
#include "scene/scene_desc.h"
#include "scene/shapes/shape_list.h"

namespace vkrt {

// The box around the scene's triangles and spheres; false (and nothing set) without geometry.
bool sceneBounds(const SceneDesc& scene, dvec3& lo, dvec3& hi);

// The shader's float32 frame: world point x is (x - origin) * scale there (flatten()).
// Its origin: the centre of the geometry's box; or the camera, without geometry or when some
// primitive comes within kFrameCentreReach times the camera's distance from that centre:
// then the centre is far from what the camera may see nearby (a far object widens the box),
// and float32 would round it more coarsely than its distance from the camera. The offsets'
// magnitude term is measured from it.
inline constexpr double kFrameCentreReach = 1.0 / 64.0;
dvec3 floatFrameOrigin(const SceneDesc& scene);

// The frame's scale: a power of two (exact in float), 1 when the largest coordinate of the
// geometry and the camera in the frame (max norm) lies within [kFrameExtentLow,
// kFrameExtentHigh], else the one that brings it into [1, 2): float32 then neither overflows
// nor underflows in squares of lengths, wherever and however large the scene is.
inline constexpr double kFrameExtentLow = 1.0 / 256.0;
inline constexpr double kFrameExtentHigh = 256.0;
double floatFrameScale(const SceneDesc& scene, const dvec3& origin);

// The course's offset (1e-3) for an object of the course's sizes, scaled by whole decades for
// an object of another size (its size: the diagonal of its box).
double offsetForSize(double size);

// The offset of every primitive: its own object's, or the smallest of the objects whose boxes
// come within that distance of it, whichever is smaller. An object is a sphere, or a set of
// triangles connected through shared vertex positions.
struct PrimitiveOffsets {
  // One per primitive of each kind, named as the SceneDesc's arrays (shapes/shape_list.h):
  // `triangles`, `spheres`.
#define VKRT_SHAPE_MEMBER(Type, member, name, kind, GpuType, binding) std::vector<double> member;
  VKRT_SHAPES(VKRT_SHAPE_MEMBER)
#undef VKRT_SHAPE_MEMBER
  int objects = 0;                 // how many objects the scene has (for --stats and tests)
  // The offsets of the primitives of `kind` (a kind of shape_list.h), and the offset of the
  // primitive that `ref` refers to.
  std::vector<double>& ofKind(std::uint32_t kind) { return this->*kindMembers()[kind]; }
  const std::vector<double>& ofKind(std::uint32_t kind) const { return this->*kindMembers()[kind]; }
  double of(std::uint32_t ref) const { return ofKind(gpu::primKind(ref))[gpu::primIndex(ref)]; }

 private:
  // The arrays by kind (the list is in the order of the kinds: shapes/shape.h).
  using Member = std::vector<double> PrimitiveOffsets::*;
  static const Member* kindMembers() {
#define VKRT_SHAPE_POINTER(Type, member, name, kind, GpuType, binding) &PrimitiveOffsets::member,
    static constexpr Member kMembers[] = {VKRT_SHAPES(VKRT_SHAPE_POINTER)};
#undef VKRT_SHAPE_POINTER
    return kMembers;
  }
};
PrimitiveOffsets primitiveOffsets(const SceneDesc& scene);

// The offsets of secondary rays leaving a hit point: the primitive's offset, or more far
// from the float32 frame's origin and from the camera (pFromOrigin, pFromCamera), where
// float32 rounds the hit point more coarsely, and more for a ray that leaves nearly along
// the surface.
struct SecondaryRayOffsets {
  double tMin = 0.0;      // for a ray leaving along the normal
  double grazing = 0.0;   // divided by |N.dir| for a ray leaving at an angle
  // The tMin of a ray leaving with |N.dir| = cosine.
  double at(double cosine) const { return std::max(tMin, grazing / std::max(cosine, 1e-30)); }
};
SecondaryRayOffsets secondaryRayOffsets(double primitiveOffset, const dvec3& pFromOrigin, const dvec3& pFromCamera);

}  // namespace vkrt
