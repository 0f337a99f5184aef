// The triangle: what the host asks of one (its box, whether it can be hit, its area, the
// CPU reference's intersection and normal, a point on it as a light and its density, how near
// it comes to a point). Listed in scene/shapes/shape_list.h. Its commands (`vertex`, `tri`,
// `vertexnormal`, `trinormal`) are the parser's: they share its vertex lists.
#pragma once

#include <cstdint>

#include "scene/shapes/ray_hit.h"

namespace vkrt {

struct Triangle {       // world space, counter-clockwise
  dvec3 p[3];
  dvec3 n[3];           // world-space unit vertex normals; meaningful only when smooth
  bool smooth = false;  // `trinormal`: normals interpolated barycentrically
  std::uint32_t material = 0;
};

}  // namespace vkrt

namespace vkrt::shapes {

// The box of its three vertices.
void bounds(const Triangle& t, dvec3& lo, dvec3& hi);

// Zero area (repeated or collinear vertices): no ray hits it, and the BVH leaves it out.
bool neverHit(const Triangle& t);

// |cross(p1 - p0, p2 - p0)| / 2.
double area(const Triangle& t);

// Plane intersection followed by an inside test on the three edge functions: the nearest t in
// (tMin, tMax), with the barycentric weights b1, b2 (hit.prim is left alone).
bool intersect(const Triangle& t, const Ray& ray, double tMin, double tMax, Hit& hit);

// The unit normal at a hit (doc/scene-format.md: never flipped toward the ray): interpolated
// from the vertex normals for a smooth triangle, else the face normal.
dvec3 normalAt(const Triangle& t, const Hit& hit, const dvec3& p);

// A point uniform in area from (u, v) in [0, 1)^2, its face normal and area density.
SurfacePoint samplePoint(const Triangle& t, double u, double v);
// The face normal and area density of samplePoint at point p of the triangle.
SurfacePoint densityAt(const Triangle& t, const dvec3& p);

// Whether the triangle comes within `reach` of p (asked of one whose box does).
bool within(const Triangle& t, const dvec3& p, double reach);

}  // namespace vkrt::shapes
