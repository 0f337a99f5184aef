// Ray queries of the CPU backends, in double precision (moved out of reference.cpp unchanged,
// so that the Whitted reference's images stay the same bytes).
#include "cpu/scene_query.h"

#include <algorithm>
#include <cmath>

#include "scene/unit_vector.h"

namespace vkrt {
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

// Plane intersection followed by an inside test on the three edge functions. The normal is
// scaled by a power of two (exact) so that its square neither underflows nor overflows.
bool hitTriangle(const Triangle& tri, const Ray& ray, double tMin, double tMax, Hit& hit) {
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

// The ray goes into object space unnormalised, so its t is the world t.
bool hitSphere(const Sphere& s, const Ray& ray, double tMin, double tMax, Hit& hit) {
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

// Slab test against a float box; true when the ray may enter it within (tMin, tMax).
bool hitBox(const gpu::GpuBvhNode& n, const Ray& ray, const dvec3& invDir, double tMin, double tMax) {
  const double lo[3] = {n.minX, n.minY, n.minZ}, hi[3] = {n.maxX, n.maxY, n.maxZ};
  for (int a = 0; a < 3; ++a) {
    if (ray.dir[a] == 0.0) {
      if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return false;
      continue;
    }
    double t0 = (lo[a] - ray.origin[a]) * invDir[a], t1 = (hi[a] - ray.origin[a]) * invDir[a];
    if (t0 > t1) std::swap(t0, t1);
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return false;
  }
  return true;
}

}  // namespace

SceneQuery::SceneQuery(const SceneDesc& scene, const Bvh& bvh) : scene_(scene), bvh_(bvh) {
  const Camera& c = scene.camera;
  w_ = unitVector(c.from - c.at);
  u_ = unitVector(glm::cross(scaledForSquares(c.up), w_));
  v_ = glm::cross(w_, u_);
  halfW_ = scene.width / 2.0;
  halfH_ = scene.height / 2.0;
  tanY_ = std::tan(glm::radians(c.fovyDegrees) / 2.0);
  tanX_ = tanY_ * scene.width / scene.height;
  offsets_ = primitiveOffsets(scene);
  frameOrigin_ = floatFrameOrigin(scene);
}

bool SceneQuery::intersect(const Ray& ray, double tMin, double tMax, bool anyHit, Hit& hit) const {
  if (bvh_.primRefs.empty()) return false;   // the root is then an empty leaf
  dvec3 invDir(1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z);
  std::uint32_t stack[kMaxBvhDepth];
  int top = 0;
  stack[top++] = 0;
  bool found = false;
  hit.t = tMax;
  while (top > 0) {
    const gpu::GpuBvhNode& node = bvh_.nodes[stack[--top]];
    if (!hitBox(node, ray, invDir, tMin, hit.t)) continue;
    if (node.primCount > 0) {
      for (std::uint32_t i = 0; i < node.primCount; ++i) {
        std::uint32_t ref = bvh_.primRefs[node.leftOrFirst + i];
        Hit h;
        bool ok = (gpu::primKind(ref) == gpu::kPrimSphere)
                      ? hitSphere(scene_.spheres[gpu::primIndex(ref)], ray, tMin, hit.t, h)
                      : hitTriangle(scene_.triangles[ref], ray, tMin, hit.t, h);
        if (ok) {
          h.prim = ref;
          hit = h;
          found = true;
          if (anyHit) return true;
        }
      }
    } else {
      stack[top++] = node.leftOrFirst + 1;
      stack[top++] = node.leftOrFirst;
    }
  }
  return found;
}

std::uint32_t SceneQuery::surfaceAt(const Hit& hit, const dvec3& p, dvec3& normal) const {
  if (gpu::primKind(hit.prim) == gpu::kPrimSphere) {
    const Sphere& s = scene_.spheres[gpu::primIndex(hit.prim)];
    dvec3 pObject = dvec3(s.objectFromWorld * glm::dvec4(p, 1.0));
    normal = glm::normalize(glm::transpose(glm::dmat3(s.objectFromWorld)) * (pObject - s.center));
    return s.material;
  }
  const Triangle& t = scene_.triangles[hit.prim];
  if (t.smooth)
    normal = glm::normalize((1.0 - hit.b1 - hit.b2) * t.n[0] + hit.b1 * t.n[1] + hit.b2 * t.n[2]);
  else
    normal = unitVector(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
  return t.material;
}

SecondaryRayOffsets SceneQuery::offsetsAt(const Hit& hit, const dvec3& p) const {
  const double primitiveOffset = (gpu::primKind(hit.prim) == gpu::kPrimSphere) ? offsets_.spheres[gpu::primIndex(hit.prim)]
                                                                  : offsets_.triangles[hit.prim];
  return secondaryRayOffsets(primitiveOffset, p - frameOrigin_, p - scene_.camera.from);
}

SecondaryRayOffsets SceneQuery::triangleOffsetsAt(std::uint32_t triangle, const dvec3& p) const {
  return secondaryRayOffsets(offsets_.triangles[triangle], p - frameOrigin_, p - scene_.camera.from);
}

Ray SceneQuery::cameraRay(double px, double py) const {
  double a = tanX_ * (px - halfW_) / halfW_;
  double b = tanY_ * (halfH_ - py) / halfH_;
  return {scene_.camera.from, glm::normalize(a * u_ + b * v_ - w_)};
}

}  // namespace vkrt
