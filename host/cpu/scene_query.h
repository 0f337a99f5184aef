// The CPU backends' ray queries: nearest and any hit through the BVH, the surface at a hit,
// the secondary-ray offsets and the camera ray, in double precision. Shared by the Whitted
// reference (reference.cpp) and the path integrators (path_reference.cpp); shares no code
// with the shader, so that the GPU comparison can catch an intersection bug.
#pragma once

#include <cstdint>

#include "scene/bvh.h"
#include "scene/ray_offset.h"
#include "scene/scene_desc.h"
#include "scene/shapes/ray_hit.h"

namespace vkrt {

class SceneQuery {
 public:
  // The camera basis and the primitives' offsets are computed once here. `scene` and `bvh`
  // must outlive the query.
  SceneQuery(const SceneDesc& scene, const Bvh& bvh);

  // Nearest hit with t in (tMin, tMax), or the first one found when anyHit. On false, `hit`
  // holds nothing to use (its t is overwritten).
  bool intersect(const Ray& ray, double tMin, double tMax, bool anyHit, Hit& hit) const;

  // The unit normal at hit point p (doc/scene-format.md, "Transforms": never flipped toward the ray); returns the
  // material index.
  std::uint32_t surfaceAt(const Hit& hit, const dvec3& p, dvec3& normal) const;

  // The offsets of secondary rays leaving hit point p of the hit's primitive (gpu_limits.h).
  SecondaryRayOffsets offsetsAt(const Hit& hit, const dvec3& p) const;
  // The same for a point p of triangle `triangle`.
  SecondaryRayOffsets triangleOffsetsAt(std::uint32_t triangle, const dvec3& p) const;

  // doc/scene-format.md, "Camera": the ray through image position (px, py) of the full image, in pixels
  // from its top-left corner; (column + 0.5, row + 0.5) is a pixel's centre.
  Ray cameraRay(double px, double py) const;

  const SceneDesc& scene() const { return scene_; }

 private:
  const SceneDesc& scene_;
  const Bvh& bvh_;
  dvec3 u_, v_, w_;
  double halfW_, halfH_, tanX_, tanY_;
  PrimitiveOffsets offsets_;   // the secondary-ray offsets (gpu_limits.h)
  dvec3 frameOrigin_;          // where the shader's float32 frame has its origin (flatten())
};

}  // namespace vkrt
