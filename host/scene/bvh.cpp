// Binned-SAH BVH build. Boxes are computed in double and rounded outward to float, so a
// traversal in either precision never misses a primitive that the exact test would hit.
#include "scene/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vkrt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = 4;
constexpr double kTraversalCost = 1.0;   // relative to one primitive test
// Below this depth, nodes are split at the object median: with at most 2^32 primitives the
// tree is then at most kMedianDepth + 32 deep, and traversal stacks of kMaxBvhDepth suffice.
constexpr int kMedianDepth = 48;
static_assert(kMedianDepth + 34 <= kMaxBvhDepth);

struct Box {
  dvec3 lo{std::numeric_limits<double>::infinity()};
  dvec3 hi{-std::numeric_limits<double>::infinity()};
  void grow(const dvec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  void grow(const Box& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  double area() const {
    if (empty()) return 0.0;
    dvec3 e = hi - lo;
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

struct BuildPrim {
  Box box;
  dvec3 centroid;
  std::uint32_t ref;
};

float roundDown(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

class Builder {
 public:
  Builder(std::vector<BuildPrim> prims, Bvh& out) : prims_(std::move(prims)), out_(out) {}

  void build() {
    out_.nodes.reserve(std::max<std::size_t>(1, 2 * prims_.size()));
    out_.nodes.emplace_back();
    split(0, 0, static_cast<std::uint32_t>(prims_.size()), 0);
    out_.primRefs.reserve(prims_.size());
    for (const auto& p : prims_) out_.primRefs.push_back(p.ref);
  }

 private:
  void setBox(std::uint32_t node, const Box& b) {
    auto& n = out_.nodes[node];
    if (b.empty()) {   // an inverted box: no ray enters it
      n.minX = n.minY = n.minZ = 1.0f;
      n.maxX = n.maxY = n.maxZ = -1.0f;
      return;
    }
    n.minX = roundDown(b.lo.x); n.minY = roundDown(b.lo.y); n.minZ = roundDown(b.lo.z);
    n.maxX = roundUp(b.hi.x);   n.maxY = roundUp(b.hi.y);   n.maxZ = roundUp(b.hi.z);
  }

  void makeLeaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
    out_.nodes[node].leftOrFirst = begin;
    out_.nodes[node].primCount = end - begin;
  }

  void split(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
    out_.depth = std::max(out_.depth, depth + 1);
    Box bounds, centroids;
    for (std::uint32_t i = begin; i < end; ++i) {
      bounds.grow(prims_[i].box);
      centroids.grow(prims_[i].centroid);
    }
    setBox(node, bounds);
    std::uint32_t count = end - begin;
    if (count <= 1) return makeLeaf(node, begin, end);

    // Find the best of (kBins - 1) planes on each axis by SAH.
    double bestCost = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestPlane = -1;
    for (int axis = 0; axis < 3; ++axis) {
      double lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
      if (!(extent > 0.0)) continue;
      Box binBox[kBins];
      std::uint32_t binCount[kBins] = {};
      double scale = kBins / extent;
      for (std::uint32_t i = begin; i < end; ++i) {
        int b = std::min(kBins - 1, static_cast<int>((prims_[i].centroid[axis] - lo) * scale));
        binBox[b].grow(prims_[i].box);
        ++binCount[b];
      }
      double rightArea[kBins];
      std::uint32_t rightCount[kBins];
      Box acc;
      std::uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(binBox[b]);
        n += binCount[b];
        rightArea[b] = acc.area();
        rightCount[b] = n;
      }
      acc = Box();
      n = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.grow(binBox[b]);
        n += binCount[b];
        if (n == 0 || rightCount[b + 1] == 0) continue;
        double cost = acc.area() * n + rightArea[b + 1] * rightCount[b + 1];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestPlane = b;
        }
      }
    }

    double parentArea = bounds.area();
    double leafCost = static_cast<double>(count);
    double splitCost = parentArea > 0.0 ? kTraversalCost + bestCost / parentArea : leafCost;
    std::uint32_t mid;
    if (depth >= kMedianDepth && count > kMaxLeafSize) {
      dvec3 e = centroids.hi - centroids.lo;
      int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
      mid = begin + count / 2;
      std::nth_element(prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end,
                       [&](const BuildPrim& a, const BuildPrim& b) { return a.centroid[axis] < b.centroid[axis]; });
    } else if (bestAxis < 0) {
      // All centroids coincide: split in the middle of the list if the leaf would be large.
      if (count <= kMaxLeafSize) return makeLeaf(node, begin, end);
      mid = begin + count / 2;
    } else {
      if (count <= kMaxLeafSize && leafCost <= splitCost) return makeLeaf(node, begin, end);
      double lo = centroids.lo[bestAxis], scale = kBins / (centroids.hi[bestAxis] - lo);
      auto it = std::partition(prims_.begin() + begin, prims_.begin() + end, [&](const BuildPrim& p) {
        return std::min(kBins - 1, static_cast<int>((p.centroid[bestAxis] - lo) * scale)) <= bestPlane;
      });
      mid = static_cast<std::uint32_t>(it - prims_.begin());
      if (mid == begin || mid == end) mid = begin + count / 2;
    }

    std::uint32_t left = static_cast<std::uint32_t>(out_.nodes.size());
    out_.nodes.emplace_back();
    out_.nodes.emplace_back();
    out_.nodes[node].leftOrFirst = left;
    out_.nodes[node].primCount = 0;
    split(left, begin, mid, depth + 1);
    split(left + 1, mid, end, depth + 1);
  }

  std::vector<BuildPrim> prims_;
  Bvh& out_;
};

}  // namespace

void sphereBounds(const Sphere& s, dvec3& lo, dvec3& hi) {
  dvec3 c = dvec3(s.worldFromObject * glm::dvec4(s.center, 1.0));
  const dmat4& m = s.worldFromObject;
  for (int row = 0; row < 3; ++row) {
    double e = s.radius * std::sqrt(m[0][row] * m[0][row] + m[1][row] * m[1][row] + m[2][row] * m[2][row]);
    lo[row] = c[row] - e;
    hi[row] = c[row] + e;
  }
}

Bvh buildBvh(const SceneDesc& scene) {
  std::vector<BuildPrim> prims;
  prims.reserve(scene.triangles.size() + scene.spheres.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    BuildPrim p;
    for (const dvec3& v : scene.triangles[i].p) p.box.grow(v);
    p.centroid = 0.5 * (p.box.lo + p.box.hi);
    p.ref = static_cast<std::uint32_t>(i);
    prims.push_back(p);
  }
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    BuildPrim p;
    sphereBounds(scene.spheres[i], p.box.lo, p.box.hi);
    p.centroid = 0.5 * (p.box.lo + p.box.hi);
    p.ref = static_cast<std::uint32_t>(i) | gpu::kPrimSphereBit;
    prims.push_back(p);
  }
  Bvh bvh;
  Builder(std::move(prims), bvh).build();
  return bvh;
}

}  // namespace vkrt
