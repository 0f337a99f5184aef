// Binned-SAH BVH build. Each primitive's box is computed in double and rounded outward to
// float once, so every node box (a union of them) is conservative for a traversal in either
// precision. Large subtrees are built on separate threads and merged in a fixed order: the
// tree is the same whatever the thread count.
#include "scene/bvh.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <thread>

namespace vkrt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = gpu::kMaxLeafPrims;   // the shader packs the count in 3 bits
constexpr float kTraversalCost = 1.0f;   // relative to one primitive test
// Below this depth, nodes are split at the object median: with at most 2^32 primitives the
// tree is then at most kMedianDepth + 32 deep, and traversal stacks of kMaxBvhDepth suffice.
constexpr int kMedianDepth = 48;
static_assert(kMedianDepth + 34 <= kMaxBvhDepth);
// Subtrees of at least this many primitives, in the top levels, are built in parallel.
constexpr std::uint32_t kParallelMinPrims = 50000;
constexpr int kParallelMaxDepth = 3;   // up to 2^3 concurrent subtrees

using glm::vec3;

struct Box {
  vec3 lo{std::numeric_limits<float>::infinity()};
  vec3 hi{-std::numeric_limits<float>::infinity()};
  void grow(const vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  void grow(const Box& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  float area() const {
    if (empty()) return 0.0f;
    vec3 e = hi - lo;
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

struct BuildPrim {
  Box box;
  std::uint32_t ref;
  // Halves first: lo + hi overflows to infinity when both are near the largest float.
  vec3 centroid() const { return 0.5f * box.lo + 0.5f * box.hi; }
};

// Maps centroids to bins along one axis. Works on halves so that no difference overflows
// (centroids may span the whole float range), and clamps in float before converting, so a
// NaN or infinite position (a coordinate beyond float) lands in a bin instead of being an
// undefined conversion. Binning and partitioning share it, so each primitive goes to the
// side that its bin was counted on.
struct Binner {
  float halfLo, scale;
  Binner(float lo, float hi) : halfLo(0.5f * lo) {
    float halfExtent = 0.5f * hi - halfLo;
    scale = halfExtent > 0.0f ? kBins / halfExtent : 0.0f;
  }
  int operator()(float c) const {
    float f = (0.5f * c - halfLo) * scale;
    if (!(f > 0.0f)) return 0;   // also NaN
    return f < static_cast<float>(kBins - 1) ? static_cast<int>(f) : kBins - 1;
  }
};

float roundDown(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

BuildPrim makePrim(const dvec3& lo, const dvec3& hi, std::uint32_t ref) {
  BuildPrim p;
  p.box.lo = {roundDown(lo.x), roundDown(lo.y), roundDown(lo.z)};
  p.box.hi = {roundUp(hi.x), roundUp(hi.y), roundUp(hi.z)};
  p.ref = ref;
  return p;
}

using Nodes = std::vector<gpu::GpuBvhNode>;

struct Split {
  int axis = -1, plane = -1;
  float cost = std::numeric_limits<float>::infinity();
};

class Builder {
 public:
  explicit Builder(std::vector<BuildPrim>& prims) : prims_(prims) {}

  // Builds the subtree of prims_[begin, end) into `out`, its root at out[root].
  void build(Nodes& out, std::uint32_t root, std::uint32_t begin, std::uint32_t end, int depth, int& maxDepth) {
    maxDepth = std::max(maxDepth, depth + 1);
    Box bounds, centroids;
    for (std::uint32_t i = begin; i < end; ++i) {
      bounds.grow(prims_[i].box);
      centroids.grow(prims_[i].centroid());
    }
    setBox(out[root], bounds);
    std::uint32_t count = end - begin;
    std::uint32_t mid;
    if (!chooseSplit(begin, end, depth, bounds, centroids, mid)) {
      out[root].leftOrFirst = begin;
      out[root].primCount = count;
      return;
    }
    out[root].primCount = 0;
    if (count >= kParallelMinPrims && depth < kParallelMaxDepth) {
      // Both halves on their own (the right on another thread), then merged: root, left
      // root, right root, the rest of the left subtree, the rest of the right.
      Nodes left(1), right(1);
      int leftDepth = 0, rightDepth = 0;
      auto task = std::async(std::launch::async, [&] { build(right, 0, mid, end, depth + 1, rightDepth); });
      build(left, 0, begin, mid, depth + 1, leftDepth);
      task.get();
      maxDepth = std::max({maxDepth, leftDepth, rightDepth});
      std::uint32_t base = static_cast<std::uint32_t>(out.size());
      out[root].leftOrFirst = base;
      std::uint32_t leftRest = base + 2, rightRest = leftRest + static_cast<std::uint32_t>(left.size()) - 1;
      auto relocate = [](gpu::GpuBvhNode n, std::uint32_t rootAt, std::uint32_t restAt) {
        if (n.primCount == 0) n.leftOrFirst = n.leftOrFirst == 0 ? rootAt : restAt + n.leftOrFirst - 1;
        return n;
      };
      out.push_back(relocate(left[0], base, leftRest));
      out.push_back(relocate(right[0], base + 1, rightRest));
      for (std::size_t i = 1; i < left.size(); ++i) out.push_back(relocate(left[i], base, leftRest));
      for (std::size_t i = 1; i < right.size(); ++i) out.push_back(relocate(right[i], base + 1, rightRest));
      return;
    }
    std::uint32_t left = static_cast<std::uint32_t>(out.size());
    out.emplace_back();
    out.emplace_back();
    out[root].leftOrFirst = left;
    build(out, left, begin, mid, depth + 1, maxDepth);
    build(out, left + 1, mid, end, depth + 1, maxDepth);
  }

 private:
  static void setBox(gpu::GpuBvhNode& n, const Box& b) {
    if (b.empty()) {   // an inverted box (only for the root of an empty scene)
      n.minX = n.minY = n.minZ = 1.0f;
      n.maxX = n.maxY = n.maxZ = -1.0f;
      return;
    }
    n.minX = b.lo.x; n.minY = b.lo.y; n.minZ = b.lo.z;
    n.maxX = b.hi.x; n.maxY = b.hi.y; n.maxZ = b.hi.z;
  }

  // The best of (kBins - 1) planes on each axis by SAH, binning all three axes in one pass.
  Split bestSplit(std::uint32_t begin, std::uint32_t end, const Box& centroids) const {
    Box binBox[3][kBins];
    std::uint32_t binCount[3][kBins] = {};
    const Binner binner[3] = {{centroids.lo.x, centroids.hi.x}, {centroids.lo.y, centroids.hi.y},
                              {centroids.lo.z, centroids.hi.z}};
    for (std::uint32_t i = begin; i < end; ++i) {
      const BuildPrim& p = prims_[i];
      vec3 c = p.centroid();
      for (int a = 0; a < 3; ++a) {
        int b = binner[a](c[a]);
        binBox[a][b].grow(p.box);
        ++binCount[a][b];
      }
    }
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(binner[axis].scale > 0.0f)) continue;
      float rightArea[kBins];
      std::uint32_t rightCount[kBins];
      Box acc;
      std::uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(binBox[axis][b]);
        n += binCount[axis][b];
        rightArea[b] = acc.area();
        rightCount[b] = n;
      }
      acc = Box();
      n = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.grow(binBox[axis][b]);
        n += binCount[axis][b];
        if (n == 0 || rightCount[b + 1] == 0) continue;
        float cost = acc.area() * static_cast<float>(n) + rightArea[b + 1] * static_cast<float>(rightCount[b + 1]);
        if (cost < best.cost) best = {axis, b, cost};
      }
    }
    return best;
  }

  // Partitions prims_[begin, end) and returns true with `mid`, or false for a leaf.
  bool chooseSplit(std::uint32_t begin, std::uint32_t end, int depth, const Box& bounds, const Box& centroids,
                   std::uint32_t& mid) {
    std::uint32_t count = end - begin;
    if (count <= 1) return false;
    if (depth >= kMedianDepth && count > kMaxLeafSize) {
      vec3 e = centroids.hi - centroids.lo;
      int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
      mid = begin + count / 2;
      std::nth_element(prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end,
                       [&](const BuildPrim& a, const BuildPrim& b) { return a.centroid()[axis] < b.centroid()[axis]; });
      return true;
    }
    Split s = bestSplit(begin, end, centroids);
    if (s.axis < 0) {
      // All centroids coincide: split in the middle of the list if the leaf would be large.
      if (count <= kMaxLeafSize) return false;
      mid = begin + count / 2;
      return true;
    }
    float parentArea = bounds.area();
    float leafCost = static_cast<float>(count);
    float splitCost = parentArea > 0.0f ? kTraversalCost + s.cost / parentArea : leafCost;
    if (count <= kMaxLeafSize && leafCost <= splitCost) return false;
    const Binner binner(centroids.lo[s.axis], centroids.hi[s.axis]);
    auto it = std::partition(prims_.begin() + begin, prims_.begin() + end,
                             [&](const BuildPrim& p) { return binner(p.centroid()[s.axis]) <= s.plane; });
    mid = static_cast<std::uint32_t>(it - prims_.begin());
    if (mid == begin || mid == end) mid = begin + count / 2;
    return true;
  }

  std::vector<BuildPrim>& prims_;
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

static bool neverHit(const Triangle& t) {
  dvec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  return !(glm::dot(n, n) > 0.0) || !std::isfinite(glm::dot(n, n));
}

static bool neverHit(const Sphere& s) {
  double det = glm::determinant(s.worldFromObject);
  const dmat4& inv = s.objectFromWorld;
  bool finite = true;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(inv[c][r]);
  return !(s.radius > 0.0) || !(det != 0.0) || !finite;
}

Bvh buildBvh(const SceneDesc& scene, const dvec3& origin) {
  std::vector<BuildPrim> prims(scene.triangles.size() + scene.spheres.size());
  const std::size_t triangles = scene.triangles.size();
  constexpr std::uint32_t kDropped = 0xFFFFFFFFu;
  auto makeRange = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      if (i < triangles) {
        const Triangle& t = scene.triangles[i];
        if (neverHit(t)) {
          prims[i].ref = kDropped;
          continue;
        }
        prims[i] = makePrim(glm::min(t.p[0], glm::min(t.p[1], t.p[2])) - origin,
                            glm::max(t.p[0], glm::max(t.p[1], t.p[2])) - origin, static_cast<std::uint32_t>(i));
      } else {
        dvec3 lo, hi;
        if (neverHit(scene.spheres[i - triangles])) {
          prims[i].ref = kDropped;
          continue;
        }
        sphereBounds(scene.spheres[i - triangles], lo, hi);
        prims[i] = makePrim(lo - origin, hi - origin, static_cast<std::uint32_t>(i - triangles) | gpu::kPrimSphereBit);
      }
    }
  };
  if (prims.size() >= kParallelMinPrims) {
    auto half = std::async(std::launch::async, makeRange, prims.size() / 2, prims.size());
    makeRange(0, prims.size() / 2);
    half.get();
  } else {
    makeRange(0, prims.size());
  }
  // Degenerate primitives (zero area, repeated or collinear vertices; zero radius or a
  // singular transform) can never be hit: they are left out, so neither backend tests them.
  std::erase_if(prims, [](const BuildPrim& p) { return p.ref == kDropped; });

  Bvh bvh;
  bvh.nodes.reserve(std::max<std::size_t>(1, 2 * prims.size()));
  bvh.nodes.emplace_back();
  Builder(prims).build(bvh.nodes, 0, 0, static_cast<std::uint32_t>(prims.size()), 0, bvh.depth);
  bvh.primRefs.resize(prims.size());
  for (std::size_t i = 0; i < prims.size(); ++i) bvh.primRefs[i] = prims[i].ref;
  return bvh;
}

}  // namespace vkrt
