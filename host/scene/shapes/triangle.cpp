#include "scene/shapes/triangle.h"

#include <cmath>

#include "scene/unit_vector.h"

namespace vkrt::shapes {
namespace {

// cross(a - q, b - q), the edge function of edge a -> b at q, computed as cross(a - q, b - a)
// (or its mirror for b -> a): from the edge itself, not from two long vectors toward q whose
// cross product cancels (a tiny triangle seen from afar would otherwise be "hit" by rounding
// noise). The two triangles that share an edge compute it from the same numbers, with
// opposite signs.
dvec3 edgeFunction(const dvec3& a, const dvec3& b, const dvec3& q) {
  const bool ordered = a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  return ordered ? glm::cross(a - q, b - a) : -glm::cross(b - q, a - b);
}

// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
dvec3 nearestOnTriangle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = va + vb + vc;
  if (!(denom != 0.0) || !std::isfinite(denom)) return a;   // degenerate: a corner will do
  return a + ab * (vb / denom) + ac * (vc / denom);
}

}  // namespace

void bounds(const Triangle& t, dvec3& lo, dvec3& hi) {
  lo = glm::min(t.p[0], glm::min(t.p[1], t.p[2]));
  hi = glm::max(t.p[0], glm::max(t.p[1], t.p[2]));
}

bool neverHit(const Triangle& t) {
  // (scaled by a power of two first: a triangle 1e-150 or 1e150 across is no degenerate one)
  return scaledForSquares(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])) == dvec3(0.0);
}

double area(const Triangle& t) { return 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])); }

// The normal is scaled by a power of two (exact) so that its square neither underflows nor
// overflows.
bool intersect(const Triangle& tri, const Ray& ray, double tMin, double tMax, Hit& hit) {
  dvec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
  dvec3 n = scaledForSquares(glm::cross(e1, e2));
  double nn = glm::dot(n, n);
  double denom = glm::dot(n, ray.dir);
  if (nn == 0.0 || denom == 0.0) return false;   // degenerate, or ray in the plane
  double t = glm::dot(n, tri.p[0] - ray.origin) / denom;
  if (!(t > tMin && t < tMax)) return false;
  dvec3 q = ray.origin + t * ray.dir;
  double w0 = glm::dot(edgeFunction(tri.p[1], tri.p[2], q), n);
  double w1 = glm::dot(edgeFunction(tri.p[2], tri.p[0], q), n);
  double w2 = glm::dot(edgeFunction(tri.p[0], tri.p[1], q), n);
  if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) return false;
  // w0 + w1 + w2 = |cross(e1, e2)| |n|: the weights over their sum, as found.
  const double sum = w0 + w1 + w2;
  if (!(sum > 0.0)) return false;
  hit.t = t;
  hit.b1 = w1 / sum;
  hit.b2 = w2 / sum;
  return true;
}

dvec3 normalAt(const Triangle& t, const Hit& hit, const dvec3&) {
  if (t.smooth) return glm::normalize((1.0 - hit.b1 - hit.b2) * t.n[0] + hit.b1 * t.n[1] + hit.b2 * t.n[2]);
  return unitVector(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
}

SurfacePoint samplePoint(const Triangle& t, double u, double v) {
  const double su = std::sqrt(u);
  SurfacePoint point = densityAt(t, dvec3(0.0));
  point.x = (1.0 - su) * t.p[0] + su * (1.0 - v) * t.p[1] + su * v * t.p[2];
  return point;
}

SurfacePoint densityAt(const Triangle& t, const dvec3& p) {
  SurfacePoint point;
  point.x = p;
  const dvec3 c = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  point.normal = glm::normalize(c);
  point.areaPdf = 2.0 / glm::length(c);
  return point;
}

bool within(const Triangle& t, const dvec3& p, double reach) {
  return glm::length(p - nearestOnTriangle(p, t.p[0], t.p[1], t.p[2])) <= reach;
}

}  // namespace vkrt::shapes
