// The sphere (an ellipsoid under its transform): what the host asks of one (its box, whether
// it can be hit, its area, the CPU reference's intersection and normal, a point on it as a
// light and its density, how near it comes to a point), its GPU layout, and its command.
// Listed in scene/shapes/shape_list.h.
#pragma once

#include <cstdint>
#include <optional>

#include "gpu_types.h"
#include "scene/shapes/ray_hit.h"
#include "scene/shapes/shape_command.h"

namespace vkrt {

struct Sphere {         // (center, radius) in object space, under worldFromObject
  dmat4 worldFromObject{1.0};
  dmat4 objectFromWorld{1.0};
  dvec3 center{0.0};
  double radius = 1.0;
  std::uint32_t material = 0;
};

}  // namespace vkrt

namespace vkrt::shapes {

// `sphere x y z radius` under the current transform; nothing (after an error at the line)
// for a negative radius or a singular transform.
std::optional<Sphere> readSphere(const ShapeCommand& command);

// Its GPU layout in the float32 frame (flatten()): world point x is (x - frameOrigin) *
// frameScale there; `rayOffset` is its secondary-ray offset in world units (ray_offset.h).
gpu::GpuSphere toGpu(const Sphere& s, const dvec3& frameOrigin, double frameScale, double rayOffset);

// World-space bounds under its transform (exact for the ellipsoid).
void bounds(const Sphere& s, dvec3& lo, dvec3& hi);

// Zero radius, a singular transform, or an inverse that is not finite: no ray hits it, and
// the BVH leaves it out.
bool neverHit(const Sphere& s);

// The area of the sphere under a uniform scale of the same volume, 4 pi r^2 |det M|^(2/3):
// its area under a similarity; under another transform an area weight (any positive number
// is unbiased for the pick of a light).
double area(const Sphere& s);

// The nearest t in (tMin, tMax); the ray goes into object space unnormalised, so its t is the
// world t (hit.prim is left alone).
bool intersect(const Sphere& s, const Ray& ray, double tMin, double tMax, Hit& hit);

// The unit normal at hit point p: the object-space normal under the inverse transpose.
dvec3 normalAt(const Sphere& s, const Hit& hit, const dvec3& p);

// A point from (u, v) in [0, 1)^2: uniform on the object-space sphere, with the density moved
// to world area by the transform's area element |det M| |M^-T n|.
SurfacePoint samplePoint(const Sphere& s, double u, double v);
// The normal and area density of samplePoint at point p of the sphere.
SurfacePoint densityAt(const Sphere& s, const dvec3& p);

// Whether the sphere's surface may come within `reach` of p, asked of one whose box does (a lower bound of its distance:
// the object-space distance over the Frobenius norm of objectFromWorld, which bounds how much
// that map stretches).
bool within(const Sphere& s, const dvec3& p, double reach);

}  // namespace vkrt::shapes
