#include "scene/shapes/sphere.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "util/text.h"
#include "scene/linear_map.h"

namespace vkrt::shapes {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The power of two that brings a sphere's radius into [1, 2) when it lies outside
// [2^-8, 2^8], else 1 (the radius as it is).
double radiusNormaliser(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius) || (radius >= 1.0 / 256.0 && radius <= 256.0)) return 1.0;
  return std::ldexp(1.0, -std::ilogb(radius));
}

// The normal and area density at the point of sphere `s` whose object-space unit normal is nObject.
void densityAtNormal(const Sphere& s, const dvec3& nObject, SurfacePoint& point) {
  const dvec3 m = glm::transpose(glm::dmat3(s.objectFromWorld)) * nObject;   // M^-T n
  const double areaElement = std::abs(glm::determinant(glm::dmat3(s.worldFromObject))) * glm::length(m);
  point.normal = glm::normalize(m);
  point.areaPdf = 1.0 / (4.0 * kPi * s.radius * s.radius * areaElement);
}

}  // namespace

std::optional<Sphere> readSphere(const ShapeCommand& command) {
  double a[4];
  if (!command.args.numbers("sphere", 4, "x y z radius", a)) return std::nullopt;
  if (a[3] < 0.0) {
    command.error("sphere radius must not be negative, got " + quoted(command.args[3]));
    return std::nullopt;
  }
  if (isSingular(glm::dmat3(command.worldFromObject))) {
    command.error("sphere under a singular transform (a scale of 0): it has no volume and no normal");
    return std::nullopt;
  }
  Sphere s;
  s.worldFromObject = command.worldFromObject;
  s.objectFromWorld = inverseAffine(command.worldFromObject);
  s.center = {a[0], a[1], a[2]};
  s.radius = a[3];
  s.material = command.material();
  return s;
}

gpu::GpuSphere toGpu(const Sphere& s, const dvec3& frameOrigin, double frameScale, double rayOffset) {
  // From the float32 frame to the world.
  const dmat4 fromFrame = glm::scale(glm::translate(dmat4(1.0), frameOrigin), dvec3(1.0 / frameScale));
  gpu::GpuSphere gs{};
  gs.rayOffset = static_cast<float>(rayOffset * frameScale);
  // From the float32 frame to coordinates centred on the sphere, in double: a sphere far
  // from the world's origin keeps float32's precision. A radius far from 1 is brought into
  // [1, 2) by a power of two (exact), so that its square neither overflows nor underflows.
  const double radiusScale = radiusNormaliser(s.radius);
  gs.objectFromWorld = gpu::mat4(glm::scale(dmat4(1.0), dvec3(radiusScale)) * glm::translate(dmat4(1.0), -s.center) *
                                 s.objectFromWorld * fromFrame);
  gs.centerRadius = {0.0f, 0.0f, 0.0f, static_cast<float>(s.radius * radiusScale)};
  gs.materialIndex = s.material;
  return gs;
}

void bounds(const Sphere& s, dvec3& lo, dvec3& hi) {
  dvec3 c = dvec3(s.worldFromObject * glm::dvec4(s.center, 1.0));
  const dmat4& m = s.worldFromObject;
  for (int row = 0; row < 3; ++row) {
    // (hypot: no square overflows or underflows, so a sphere scaled by 1e160 or 1e-160 gets its box)
    double e = s.radius * std::hypot(m[0][row], m[1][row], m[2][row]);
    lo[row] = c[row] - e;
    hi[row] = c[row] + e;
  }
}

bool neverHit(const Sphere& s) {
  const dmat4& inv = s.objectFromWorld;
  bool finite = true;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(inv[c][r]);
  return !(s.radius > 0.0) || isSingular(glm::dmat3(s.worldFromObject)) || !finite;
}

double area(const Sphere& s) {
  const double scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(s.worldFromObject))));
  return 4.0 * kPi * s.radius * s.radius * scale * scale;
}

bool intersect(const Sphere& s, const Ray& ray, double tMin, double tMax, Hit& hit) {
  dvec3 o = dvec3(s.objectFromWorld * glm::dvec4(ray.origin, 1.0)) - s.center;
  dvec3 d = dvec3(s.objectFromWorld * glm::dvec4(ray.dir, 0.0));
  double a = glm::dot(d, d);
  double halfB = glm::dot(o, d);
  double c = glm::dot(o, o) - s.radius * s.radius;
  double disc = halfB * halfB - a * c;
  if (disc < 0.0 || a == 0.0) return false;
  double root = std::sqrt(disc);
  double tNear = (-halfB - root) / a, tFar = (-halfB + root) / a;
  double t = tNear > tMin ? tNear : tFar;
  if (!(t > tMin && t < tMax)) return false;
  hit.t = t;
  return true;
}

dvec3 normalAt(const Sphere& s, const Hit&, const dvec3& p) {
  dvec3 pObject = dvec3(s.objectFromWorld * glm::dvec4(p, 1.0));
  return glm::normalize(glm::transpose(glm::dmat3(s.objectFromWorld)) * (pObject - s.center));
}

SurfacePoint samplePoint(const Sphere& s, double u, double v) {
  const double z = 1.0 - 2.0 * u, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * v;
  const dvec3 nObject(r * std::cos(phi), r * std::sin(phi), z);
  SurfacePoint point;
  point.x = dvec3(s.worldFromObject * glm::dvec4(s.center + s.radius * nObject, 1.0));
  densityAtNormal(s, nObject, point);
  return point;
}

SurfacePoint densityAt(const Sphere& s, const dvec3& p) {
  SurfacePoint point;
  point.x = p;
  const dvec3 pObject = dvec3(s.objectFromWorld * glm::dvec4(p, 1.0));
  densityAtNormal(s, glm::normalize(pObject - s.center), point);
  return point;
}

bool within(const Sphere& s, const dvec3& p, double reach) {
  const glm::dmat3 m(s.objectFromWorld);
  double frobenius = 0.0;
  for (int c = 0; c < 3; ++c) frobenius += glm::dot(m[c], m[c]);
  const double inObject = std::abs(glm::length(dvec3(s.objectFromWorld * glm::dvec4(p, 1.0)) - s.center) - s.radius);
  return !(inObject > reach * std::sqrt(frobenius));
}

}  // namespace vkrt::shapes
