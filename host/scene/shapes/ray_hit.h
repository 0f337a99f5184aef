// What the shapes' queries take and give: a ray, a hit along it, and a point chosen on a
// surface with its density. Double precision, world space (the CPU reference's numbers).
#pragma once

#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace vkrt {

using glm::dmat4;
using glm::dvec3;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
  dvec3 origin;
  dvec3 dir;   // unit length
};

struct Hit {
  double t = kInfinity;
  std::uint32_t prim = 0;      // primRef (gpu_types.h): primRef(kind, index)
  double b1 = 0.0, b2 = 0.0;   // barycentric weights of p1 and p2 (triangles)
};

// A point on a surface as a light sample finds it.
struct SurfacePoint {
  dvec3 x;                 // the point
  dvec3 normal;            // unit geometric normal there (emission is two-sided)
  double areaPdf = 0.0;    // density per unit world area of choosing this point, given its primitive
};

}  // namespace vkrt
