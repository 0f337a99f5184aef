// CPU reference renderer. Double precision throughout; a plain loop over the mirror bounces
// (the shader's is a suspendable state machine in float, written apart on purpose).
#include "cpu/reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#include "scene/ray_offset.h"

namespace vkrt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kTile = 16;

// The nearest float; beyond float's range, +-infinity (a plain cast would be undefined there).
float toFloat(double c) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (c > kMax) return std::numeric_limits<float>::infinity();
  if (c < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(c);
}

struct Ray {
  dvec3 origin;
  dvec3 dir;   // unit length
};

struct Hit {
  double t = kInf;
  std::uint32_t prim = 0;      // primRef
  double b1 = 0.0, b2 = 0.0;   // barycentric weights of p1 and p2 (triangles)
};

// ---- intersection (double) ------------------------------------------------------------------

// Plane intersection followed by an inside test on the three edge functions.
bool hitTriangle(const Triangle& tri, const Ray& ray, double tMin, double tMax, Hit& hit) {
  dvec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
  dvec3 n = glm::cross(e1, e2);
  double nn = glm::dot(n, n);
  double denom = glm::dot(n, ray.dir);
  if (nn == 0.0 || denom == 0.0) return false;   // degenerate, or ray in the plane
  double t = glm::dot(n, tri.p[0] - ray.origin) / denom;
  if (!(t > tMin && t < tMax)) return false;
  dvec3 q = ray.origin + t * ray.dir;
  double w0 = glm::dot(glm::cross(tri.p[1] - q, tri.p[2] - q), n);
  double w1 = glm::dot(glm::cross(tri.p[2] - q, tri.p[0] - q), n);
  double w2 = glm::dot(glm::cross(tri.p[0] - q, tri.p[1] - q), n);
  if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) return false;
  hit.t = t;
  hit.b1 = w1 / nn;
  hit.b2 = w2 / nn;
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

class Tracer {
 public:
  // The camera basis is computed once here, not per pixel.
  Tracer(const SceneDesc& scene, const Bvh& bvh) : scene_(scene), bvh_(bvh) {
    const Camera& c = scene.camera;
    w_ = glm::normalize(c.from - c.at);
    u_ = glm::normalize(glm::cross(c.up, w_));
    v_ = glm::cross(w_, u_);
    halfW_ = scene.width / 2.0;
    halfH_ = scene.height / 2.0;
    tanY_ = std::tan(glm::radians(c.fovyDegrees) / 2.0);
    tanX_ = tanY_ * scene.width / scene.height;
    offsets_ = primitiveOffsets(scene);
    frameOrigin_ = floatFrameOrigin(scene);
  }

  // Nearest hit with t in (tMin, tMax), or the first one found when anyHit.
  bool intersect(const Ray& ray, double tMin, double tMax, bool anyHit, Hit& hit) const {
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
          bool ok = (ref & gpu::kPrimSphereBit)
                        ? hitSphere(scene_.spheres[ref & ~gpu::kPrimSphereBit], ray, tMin, hit.t, h)
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

  // The unit normal at hit point p (SPEC 4: never flipped toward the ray) and the material.
  std::uint32_t surfaceAt(const Hit& hit, const dvec3& p, dvec3& normal) const {
    if (hit.prim & gpu::kPrimSphereBit) {
      const Sphere& s = scene_.spheres[hit.prim & ~gpu::kPrimSphereBit];
      dvec3 pObject = dvec3(s.objectFromWorld * glm::dvec4(p, 1.0));
      normal = glm::normalize(glm::transpose(glm::dmat3(s.objectFromWorld)) * (pObject - s.center));
      return s.material;
    }
    const Triangle& t = scene_.triangles[hit.prim];
    if (t.smooth)
      normal = glm::normalize((1.0 - hit.b1 - hit.b2) * t.n[0] + hit.b1 * t.n[1] + hit.b2 * t.n[2]);
    else
      normal = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    return t.material;
  }

  // A hit's own colour, everything of SPEC 5 but the mirror term: A + Em + the lights, each
  // behind its shadow ray (which starts `offset` from p).
  dvec3 localShading(const Material& m, const dvec3& p, const dvec3& normal, const dvec3& eye,
                     const SecondaryRayOffsets& offset,
                     RayCounts& counts) const {
    dvec3 color = m.ambient + m.emission;
    for (const Light& light : scene_.lights) {
      dvec3 toLight;
      double distance = kInf, divisor = 1.0;
      if (light.type == LightType::Point) {
        dvec3 v = light.vec - p;
        distance = glm::length(v);
        if (distance == 0.0) continue;
        toLight = v / distance;
        divisor = light.attenuation.x + light.attenuation.y * distance + light.attenuation.z * distance * distance;
      } else {
        toLight = light.vec;
      }
      double nDotL = glm::dot(normal, toLight);
      if (nDotL <= 0.0) continue;   // SPEC 7: no diffuse and no specular from behind
      ++counts.shadow;
      Hit blocker;
      if (intersect({p, toLight}, offset.at(nDotL), distance, true, blocker)) continue;
      dvec3 half = glm::normalize(toLight + eye);
      double nDotH = std::max(glm::dot(normal, half), 0.0);
      // pow(0, 0) = 1 (C's definition; the shader states the same).
      dvec3 lit = m.diffuse * nDotL + m.specular * std::pow(nDotH, m.shininess);
      // Finite even for a tiny divisor, so that a zero material term times it stays 0, not NaN.
      constexpr double kMax = std::numeric_limits<double>::max();
      color += glm::clamp(light.color / divisor, dvec3(-kMax), dvec3(kMax)) * lit;
    }
    return color;
  }

  // The colour seen along a camera ray: SPEC section 5 with the mirror term unrolled into a
  // loop. Segment k adds throughput_k * local_k, where local_k is its hit's own shading and
  // throughput_k the product of the specular colours of the k hits before it, so
  //   radiance = local_0 + s_0 local_1 + s_0 s_1 local_2 + ...   (at most maxDepth + 1 segments)
  // which is the recursion I = local + S * I_R of SPEC 5, evaluated from the front (rounded
  // unlike the nested form only in the last bits: every course and project scene gives the
  // same bytes either way). The loop needs no stack, so every maxdepth the parser accepts
  // (up to 1,000,000) is safe.
  dvec3 trace(Ray ray, RayCounts& counts) const {
    dvec3 radiance(0.0), throughput(1.0);
    double tMin = 0.0;   // the primary ray starts at the camera; secondary rays at their offset
    for (int depth = 0;; ++depth) {
      Hit hit;
      if (!intersect(ray, tMin, kInf, false, hit)) break;   // a miss is black
      dvec3 p = ray.origin + hit.t * ray.dir;
      dvec3 normal;
      std::uint32_t materialIndex = surfaceAt(hit, p, normal);
      const Material& m = scene_.materials[materialIndex];
      const SecondaryRayOffsets offset = secondaryRayOffsets(
          (hit.prim & gpu::kPrimSphereBit) ? offsets_.spheres[hit.prim & ~gpu::kPrimSphereBit] : offsets_.triangles[hit.prim],
          p - frameOrigin_, p - scene_.camera.from);
      radiance += throughput * localShading(m, p, normal, -ray.dir, offset, counts);
      // Possibly continue along the mirror direction.
      if (depth >= scene_.maxDepth || m.specular == dvec3(0.0)) break;
      ++counts.reflection;
      throughput *= m.specular;
      dvec3 r = ray.dir - 2.0 * glm::dot(ray.dir, normal) * normal;
      ray = {p, glm::normalize(r)};
      tMin = offset.at(std::abs(glm::dot(ray.dir, normal)));
    }
    return radiance;
  }

  // SPEC section 3: the ray through the centre of pixel (column, row).
  Ray cameraRay(int column, int row) const {
    double a = tanX_ * ((column + 0.5) - halfW_) / halfW_;
    double b = tanY_ * (halfH_ - (row + 0.5)) / halfH_;
    return {scene_.camera.from, glm::normalize(a * u_ + b * v_ - w_)};
  }

 private:
  const SceneDesc& scene_;
  const Bvh& bvh_;
  dvec3 u_, v_, w_;
  double halfW_, halfH_, tanX_, tanY_;
  PrimitiveOffsets offsets_;   // the secondary-ray offsets (gpu_types.h, "Secondary rays")
  dvec3 frameOrigin_;          // where the shader's float32 frame has its origin (flatten())
};

}  // namespace

RadianceImage renderReference(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options,
                              RayCounts* counts) {
  const PixelRect region = options.crop ? *options.crop : PixelRect{0, 0, scene.width, scene.height};
  RadianceImage image(region.width(), region.height());
  image.samples = options.sampleCount;   // the mean of identical samples is the one traced
  Tracer tracer(scene, bvh);
  const int tilesX = (region.width() + kTile - 1) / kTile, tilesY = (region.height() + kTile - 1) / kTile;
  const int tileCount = tilesX * tilesY;
  const std::uint64_t totalPixels = static_cast<std::uint64_t>(region.width()) * region.height();
  std::atomic<int> nextTile{0};
  std::mutex mutex;   // guards doneCount, the progress callback and the totals
  std::uint64_t donePixels = 0;
  RayCounts totals;

  auto worker = [&] {
    RayCounts local;
    for (int tile; (tile = nextTile.fetch_add(1)) < tileCount;) {
      if (options.stop && options.stop()) break;
      // (x, y): the full image's pixel; its place in `image` is relative to the region.
      int x0 = region.x0 + (tile % tilesX) * kTile, y0 = region.y0 + (tile / tilesX) * kTile;
      int x1 = std::min(x0 + kTile, region.x1), y1 = std::min(y0 + kTile, region.y1);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          ++local.primary;
          dvec3 c = tracer.trace(tracer.cameraRay(x, y), local);
          float* px = image.pixel(x - region.x0, y - region.y0);
          for (int k = 0; k < 3; ++k) px[k] = toFloat(c[k]);
          if (!std::isfinite(c.x + c.y + c.z)) ++local.nonFinite;
        }
      std::lock_guard lock(mutex);
      donePixels += static_cast<std::uint64_t>(x1 - x0) * (y1 - y0);
      if (options.progress) options.progress(donePixels, totalPixels);
    }
    std::lock_guard lock(mutex);
    totals.primary += local.primary;
    totals.shadow += local.shadow;
    totals.reflection += local.reflection;
    totals.nonFinite += local.nonFinite;
  };

  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, tileCount));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (counts) *counts = totals;
  return image;
}

}  // namespace vkrt
