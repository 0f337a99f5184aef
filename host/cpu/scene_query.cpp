// Ray queries of the CPU backends, in double precision (moved out of reference.cpp unchanged,
// so that the Whitted reference's images stay the same bytes).
#include "cpu/scene_query.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/shape.h"
#include "scene/unit_vector.h"

namespace vkrt {
namespace {

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
        if (shapes::intersect(scene_, ref, ray, tMin, hit.t, h)) {
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
  normal = shapes::normalAt(scene_, hit, p);
  return shapes::material(scene_, hit.prim);
}

SecondaryRayOffsets SceneQuery::offsetsAt(const Hit& hit, const dvec3& p) const {
  return secondaryRayOffsets(offsets_.of(hit.prim), p - frameOrigin_, p - scene_.camera.from);
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
