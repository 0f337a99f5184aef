// The secondary-ray offset policy: how far a shadow or mirror ray leaving a primitive ignores
// hits. The policy is stated once, in gpu_types.h ("Secondary rays"); both backends take their
// numbers from here. Depends on the scene description only.
#pragma once

#include <algorithm>
#include <vector>

#include "scene/scene_desc.h"

namespace vkrt {

// The box around the scene's triangles and spheres; false (and nothing set) without geometry.
bool sceneBounds(const SceneDesc& scene, dvec3& lo, dvec3& hi);

// Where flatten() puts the origin of the shader's float32 frame: the centre of the geometry's
// box, or the camera without geometry. The offsets' magnitude term is measured from it.
dvec3 floatFrameOrigin(const SceneDesc& scene);

// The course's offset (1e-3) for an object of the course's sizes, scaled by whole decades for
// an object of another size (its size: the diagonal of its box).
double offsetForSize(double size);

// The offset of every primitive: its own object's, or the smallest of the objects whose boxes
// come within that distance of it, whichever is smaller. An object is a sphere, or a set of
// triangles connected through shared vertex positions.
struct PrimitiveOffsets {
  std::vector<double> triangles;   // one per SceneDesc triangle
  std::vector<double> spheres;     // one per SceneDesc sphere
  int objects = 0;                 // how many objects the scene has (for --stats and tests)
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
