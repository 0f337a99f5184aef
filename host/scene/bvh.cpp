// Binned-SAH BVH build. Each primitive's box is computed in double and rounded outward to
// float once, so every node box (a union of them) is conservative for a traversal in either
// precision. Large subtrees are built on separate threads and merged in a fixed order: the
// tree is the same whatever the thread count.
#include "scene/bvh.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <future>
#include <limits>
#include <string>
#include <thread>

#include "util/errors.h"
#include "scene/shapes/shape.h"

namespace vkrt {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafSize = gpu::kMaxLeafPrims;   // the shader packs the count in 3 bits
constexpr float kTraversalCost = 1.0f;   // relative to one primitive test
// Below this depth, nodes are split at the object median: with at most 2^32 primitives the
// tree is then at most kMedianDepth + 32 deep, and traversal stacks of kMaxBvhDepth suffice.
constexpr int kMedianDepth = 48;
static_assert(kMedianDepth + 34 <= kMaxBvhDepth);
// A subtree of at least this many primitives is built on another thread when a core is idle.
constexpr std::uint32_t kParallelMinPrims = 4096;
// Primitive boxes are made on two threads from this many primitives on.
constexpr std::size_t kParallelBoxesMinPrims = 50000;
// Nodes of three up to this many primitives (their share of scene7's nodes: bench/README.md,
// "Host stages: parse, BVH build, flatten") try only the planes between their primitives'
// bins, without clearing and sweeping all the bins.
constexpr std::uint32_t kSparseMaxPrims = 4;

// Four floats in one register (GCC and Clang vector extensions: SSE, NEON, or scalar code).
// Lane 3 of every box and centroid is 0.
typedef float F4 __attribute__((vector_size(16)));
typedef std::int32_t I4 __attribute__((vector_size(16)));

// glm::min and glm::max, lane by lane, with their operand order.
inline F4 vmin(F4 a, F4 b) { return b < a ? b : a; }
inline F4 vmax(F4 a, F4 b) { return a < b ? b : a; }

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Box {
  F4 lo = {kInf, kInf, kInf, 0.0f};
  F4 hi = {-kInf, -kInf, -kInf, 0.0f};
  void grow(F4 p) { lo = vmin(lo, p); hi = vmax(hi, p); }
  void grow(F4 pLo, F4 pHi) { lo = vmin(lo, pLo); hi = vmax(hi, pHi); }
  void grow(const Box& b) { grow(b.lo, b.hi); }
  bool empty() const { return lo[0] > hi[0]; }
  float area() const {
    if (empty()) return 0.0f;
    const float ex = hi[0] - lo[0], ey = hi[1] - lo[1], ez = hi[2] - lo[2];
    return 2.0f * (ex * ey + ey * ez + ez * ex);
  }
};

// A primitive's box, rounded outward to float, and what it refers to (kept in lane 3 of the
// box's low corner, masked off before any arithmetic).
struct alignas(16) BuildPrim {
  float lo[3];
  std::uint32_t ref;
  float hi[3];
  float zero = 0.0f;
};
static_assert(sizeof(BuildPrim) == 32);

constexpr I4 kXyzMask = {-1, -1, -1, 0};
inline F4 loOf(const BuildPrim& p) {
  I4 v;
  std::memcpy(&v, p.lo, sizeof v);
  return reinterpret_cast<F4>(v & kXyzMask);
}
inline F4 hiOf(const BuildPrim& p) {
  F4 v;
  std::memcpy(&v, p.hi, sizeof v);
  return v;
}
// Halves first: lo + hi overflows to infinity when both are near the largest float.
inline F4 centroidOf(F4 lo, F4 hi) { return 0.5f * lo + 0.5f * hi; }

// The boxes of a node's primitives and of their centroids.
struct Bounds {
  Box box, centroids;
  void add(const BuildPrim& p) {
    const F4 lo = loOf(p), hi = hiOf(p);
    box.grow(lo, hi);
    centroids.grow(centroidOf(lo, hi));
  }
};

// Maps centroids to bins along each axis. Works on halves so that no difference overflows
// (centroids may span the whole float range), and clamps in float before converting, so a
// NaN or infinite position (a coordinate beyond float) lands in a bin instead of being an
// undefined conversion. Binning and partitioning share it, so each primitive goes to the
// side that its bin was counted on.
struct Binner {
  F4 halfLo = {}, scale = {};
  explicit Binner(const Box& centroids) {
    for (int a = 0; a < 3; ++a) {
      halfLo[a] = 0.5f * centroids.lo[a];
      const float halfExtent = 0.5f * centroids.hi[a] - halfLo[a];
      scale[a] = halfExtent > 0.0f ? kBins / halfExtent : 0.0f;
    }
  }
  I4 bins(F4 c) const {
    F4 f = (0.5f * c - halfLo) * scale;
    const F4 zero = {}, last = {kBins - 1, kBins - 1, kBins - 1, kBins - 1};
    f = f > zero ? f : zero;   // also NaN
    f = f < last ? f : last;
    return __builtin_convertvector(f, I4);
  }
  int bin(F4 c, int axis) const {
    const float f = (0.5f * c[axis] - halfLo[axis]) * scale[axis];
    if (!(f > 0.0f)) return 0;   // also NaN
    return f < static_cast<float>(kBins - 1) ? static_cast<int>(f) : kBins - 1;
  }
};

// The float next to f toward -infinity (down) or +infinity (up), for a float that has one (not
// NaN, not the infinity it moves away from): std::nextafter without the library call.
float nextFloat(float f, bool up) {
  if (f == 0.0f) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  return std::bit_cast<float>((f > 0.0f) == up ? bits + 1 : bits - 1);
}
float roundDown(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? nextFloat(f, false) : f;
}
float roundUp(double v) {
  float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? nextFloat(f, true) : f;
}

BuildPrim makePrim(const dvec3& lo, const dvec3& hi, std::uint32_t ref) {
  BuildPrim p;
  p.lo[0] = roundDown(lo.x), p.lo[1] = roundDown(lo.y), p.lo[2] = roundDown(lo.z);
  p.hi[0] = roundUp(hi.x), p.hi[1] = roundUp(hi.y), p.hi[2] = roundUp(hi.z);
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
  Builder(std::vector<BuildPrim>& prims, int threads) : prims_(prims), threads_(threads) {}

  // Builds the subtree of prims_[begin, end), whose bounds are `bounds`, into `out`, its root
  // at out[root]. The children of a node follow each other, and each subtree's nodes follow
  // its root's children depth first (left, then right), whichever thread builds them: the
  // tree and its layout are the same for every thread count.
  void build(Nodes& out, std::uint32_t root, std::uint32_t begin, std::uint32_t end, int depth,
             const Bounds& bounds, int& maxDepth) {
    maxDepth = std::max(maxDepth, depth + 1);
    setBox(out[root], bounds.box);
    std::uint32_t mid;
    Bounds left, right;
    if (!chooseSplit(begin, end, depth, bounds, mid, left, right)) {
      out[root].leftOrFirst = begin;
      out[root].primCount = end - begin;
      return;
    }
    const std::uint32_t children = static_cast<std::uint32_t>(out.size());
    out[root].leftOrFirst = children;
    out[root].primCount = 0;
    out.emplace_back();
    out.emplace_back();
    if (end - mid >= kParallelMinPrims && mid - begin >= kParallelMinPrims && reserveThread()) {
      // The right subtree on another thread into a list of its own, appended after the left.
      Nodes rightNodes(1);
      rightNodes.reserve(2 * (end - mid));   // at most 2n - 1 nodes: no reallocation
      int rightDepth = 0;
      auto task = std::async(std::launch::async, [&] {
        build(rightNodes, 0, mid, end, depth + 1, right, rightDepth);
        busy_.fetch_sub(1);
      });
      build(out, children, begin, mid, depth + 1, left, maxDepth);
      busy_.fetch_sub(1);   // this thread waits: another may start meanwhile
      task.get();
      busy_.fetch_add(1);
      maxDepth = std::max(maxDepth, rightDepth);
      const std::uint32_t restAt = static_cast<std::uint32_t>(out.size());
      auto relocate = [restAt](gpu::GpuBvhNode n) {
        if (n.primCount == 0) n.leftOrFirst = restAt + n.leftOrFirst - 1;
        return n;
      };
      out[children + 1] = relocate(rightNodes[0]);
      out.reserve(out.size() + rightNodes.size() - 1);
      for (std::size_t i = 1; i < rightNodes.size(); ++i) out.push_back(relocate(rightNodes[i]));
      return;
    }
    build(out, children, begin, mid, depth + 1, left, maxDepth);
    build(out, children + 1, mid, end, depth + 1, right, maxDepth);
  }

 private:
  bool reserveThread() {
    int busy = busy_.load();
    while (busy < threads_)
      if (busy_.compare_exchange_weak(busy, busy + 1)) return true;
    return false;
  }

  static void setBox(gpu::GpuBvhNode& n, const Box& b) {
    if (b.empty()) {   // an inverted box (only for the root of an empty scene)
      n.minX = n.minY = n.minZ = 1.0f;
      n.maxX = n.maxY = n.maxZ = -1.0f;
      return;
    }
    n.minX = b.lo[0]; n.minY = b.lo[1]; n.minZ = b.lo[2];
    n.maxX = b.hi[0]; n.maxY = b.hi[1]; n.maxZ = b.hi[2];
  }

  Bounds boundsOf(std::uint32_t begin, std::uint32_t end) const {
    Bounds b;
    for (std::uint32_t i = begin; i < end; ++i) b.add(prims_[i]);
    return b;
  }

  // The best of (kBins - 1) planes on each axis by SAH, binning all three axes in one pass.
  // Only the planes just above an occupied bin are tried: a plane between empty bins splits
  // the primitives as the plane below it does, at the same cost, and the first of equal cost
  // is kept. (A node of a few primitives occupies a few bins.)
  Split bestSplit(std::uint32_t begin, std::uint32_t end, const Binner& binner) const {
    if (end - begin == 2) return bestSplitOfTwo(begin, binner);
    if (end - begin <= kSparseMaxPrims) return bestSplitSparse(begin, end, binner);
    Box binBox[3][kBins];
    std::uint32_t binCount[3][kBins] = {};
    std::uint32_t occupied[3] = {};   // bit b: bin b holds a primitive
    for (std::uint32_t i = begin; i < end; ++i) {
      const F4 lo = loOf(prims_[i]), hi = hiOf(prims_[i]);
      const I4 b = binner.bins(centroidOf(lo, hi));
      for (int a = 0; a < 3; ++a) {
        binBox[a][b[a]].grow(lo, hi);
        ++binCount[a][b[a]];
        occupied[a] |= 1u << b[a];
      }
    }
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      const std::uint32_t bins = occupied[axis];
      if (!(binner.scale[axis] > 0.0f) || (bins & (bins - 1)) == 0) continue;   // fewer than 2 bins
      // What lies at or above each occupied bin but the lowest.
      float rightArea[kBins];
      std::uint32_t rightCount[kBins];
      Box acc;
      std::uint32_t n = 0;
      for (std::uint32_t rest = bins & (bins - 1); rest != 0;) {
        const int b = std::bit_width(rest) - 1;   // the highest left
        rest &= ~(1u << b);
        acc.grow(binBox[axis][b]);
        n += binCount[axis][b];
        rightArea[b] = acc.area();
        rightCount[b] = n;
      }
      acc = Box();
      n = 0;
      const int highest = std::bit_width(bins) - 1;
      for (std::uint32_t rest = bins; ;) {
        const int b = std::countr_zero(rest);   // the lowest left
        if (b == highest) break;
        rest &= rest - 1;
        const int above = std::countr_zero(rest);
        acc.grow(binBox[axis][b]);
        n += binCount[axis][b];
        float cost = acc.area() * static_cast<float>(n) + rightArea[above] * static_cast<float>(rightCount[above]);
        if (cost < best.cost) best = {axis, b, cost};
      }
    }
    return best;
  }

  // bestSplit() of two primitives (many nodes: bench/README.md, "Host stages: parse, BVH
  // build, flatten"), without the bins. On an axis where
  // their centroids differ (the centroids' box is theirs), one falls in the first bin and the
  // other in the last; the split is the same on every such axis, at the cost of the two boxes'
  // areas, so the sweep keeps the first.
  Split bestSplitOfTwo(std::uint32_t first, const Binner& binner) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (!(binner.scale[axis] > 0.0f)) continue;
      Box a, b;
      a.grow(loOf(prims_[first]), hiOf(prims_[first]));
      b.grow(loOf(prims_[first + 1]), hiOf(prims_[first + 1]));
      return {axis, 0, a.area() * 1.0f + b.area() * 1.0f};
    }
    return {};
  }

  // bestSplit() for a few primitives: the same split, trying only the planes that separate
  // primitives (a plane between empty bins has the cost of the occupied bin before it, and
  // the sweep keeps the first plane of equal cost).
  Split bestSplitSparse(std::uint32_t begin, std::uint32_t end, const Binner& binner) const {
    const std::uint32_t count = end - begin;
    F4 lo[kSparseMaxPrims], hi[kSparseMaxPrims];
    I4 bins[kSparseMaxPrims];
    for (std::uint32_t i = 0; i < count; ++i) {
      lo[i] = loOf(prims_[begin + i]);
      hi[i] = hiOf(prims_[begin + i]);
      bins[i] = binner.bins(centroidOf(lo[i], hi[i]));
    }
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(binner.scale[axis] > 0.0f)) continue;
      std::uint32_t order[kSparseMaxPrims];
      for (std::uint32_t i = 0; i < count; ++i) {   // insertion sort by bin
        std::uint32_t j = i;
        for (; j > 0 && bins[order[j - 1]][axis] > bins[i][axis]; --j) order[j] = order[j - 1];
        order[j] = i;
      }
      float rightArea[kSparseMaxPrims];
      Box acc;
      for (std::uint32_t j = count - 1; j > 0; --j) {
        acc.grow(lo[order[j]], hi[order[j]]);
        rightArea[j] = acc.area();
      }
      acc = Box();
      for (std::uint32_t j = 1; j < count; ++j) {
        const std::uint32_t last = order[j - 1];
        acc.grow(lo[last], hi[last]);
        if (bins[last][axis] == bins[order[j]][axis]) continue;
        float cost = acc.area() * static_cast<float>(j) + rightArea[j] * static_cast<float>(count - j);
        if (cost < best.cost) best = {axis, bins[last][axis], cost};
      }
    }
    return best;
  }

  // std::partition's order (libstdc++: from both ends, swapping), measuring both sides.
  std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const Binner& binner, const Split& s,
                          Bounds& left, Bounds& right) {
    BuildPrim* first = prims_.data() + begin;
    BuildPrim* last = prims_.data() + end;
    auto goesLeft = [&](const BuildPrim& p) {
      const F4 lo = loOf(p), hi = hiOf(p), c = centroidOf(lo, hi);
      const bool isLeft = binner.bin(c, s.axis) <= s.plane;
      Bounds& side = isLeft ? left : right;
      side.box.grow(lo, hi);
      side.centroids.grow(c);
      return isLeft;
    };
    for (;;) {
      for (;; ++first) {
        if (first == last) return static_cast<std::uint32_t>(first - prims_.data());
        if (!goesLeft(*first)) break;
      }
      --last;
      for (;; --last) {
        if (first == last) return static_cast<std::uint32_t>(first - prims_.data());
        if (goesLeft(*last)) break;
      }
      std::swap(*first, *last);
      ++first;
    }
  }

  // Partitions prims_[begin, end) and returns true with `mid` and both sides' bounds, or false
  // for a leaf.
  bool chooseSplit(std::uint32_t begin, std::uint32_t end, int depth, const Bounds& bounds, std::uint32_t& mid,
                   Bounds& left, Bounds& right) {
    std::uint32_t count = end - begin;
    if (count <= 1) return false;
    if (depth >= kMedianDepth && count > kMaxLeafSize) {
      const Box& c = bounds.centroids;
      const float ex = c.hi[0] - c.lo[0], ey = c.hi[1] - c.lo[1], ez = c.hi[2] - c.lo[2];
      const int axis = ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
      mid = begin + count / 2;
      std::nth_element(prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end,
                       [axis](const BuildPrim& a, const BuildPrim& b) {
                         return centroidOf(loOf(a), hiOf(a))[axis] < centroidOf(loOf(b), hiOf(b))[axis];
                       });
      left = boundsOf(begin, mid);
      right = boundsOf(mid, end);
      return true;
    }
    const Binner binner(bounds.centroids);
    Split s = bestSplit(begin, end, binner);
    if (s.axis < 0) {
      // All centroids coincide: split in the middle of the list if the leaf would be large.
      if (count <= kMaxLeafSize) return false;
      mid = begin + count / 2;
      left = boundsOf(begin, mid);
      right = boundsOf(mid, end);
      return true;
    }
    float parentArea = bounds.box.area();
    float leafCost = static_cast<float>(count);
    float splitCost = parentArea > 0.0f ? kTraversalCost + s.cost / parentArea : leafCost;
    if (count <= kMaxLeafSize && leafCost <= splitCost) return false;
    mid = partition(begin, end, binner, s, left, right);
    if (mid == begin || mid == end) {
      mid = begin + count / 2;
      left = boundsOf(begin, mid);
      right = boundsOf(mid, end);
    }
    return true;
  }

  std::vector<BuildPrim>& prims_;
  const int threads_;
  std::atomic<int> busy_{1};   // threads building now (this one included)
};

}  // namespace

void checkPrimitiveCounts(const SceneDesc& scene) {
  // A primitive reference holds an index below 2^29 (gpu_types.h, primRef): 32 GiB of
  // triangles, beyond any machine's memory before this is reached.
  bool tooMany = false;
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind)
    tooMany = tooMany || shapes::count(scene, kind) > gpu::kPrimIndexMask;
  if (tooMany) {
    std::string counts;   // "N triangles and M spheres", every kind
    for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind)
      counts += std::string(kind == 0 ? "" : kind + 1 < shapes::kKinds ? ", " : " and ") +
                std::to_string(shapes::count(scene, kind)) + " " + std::string(shapes::kPluralNames[kind]);
    throw OutOfMemory(counts + ": a scene holds at most " + std::to_string(gpu::kPrimIndexMask) + " of each");
  }
}

Bvh buildBvh(const SceneDesc& scene, const dvec3& origin, int threads, double scale) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  checkPrimitiveCounts(scene);
  // Every primitive of kind 0, then of kind 1, ...: prims[i] for i in [first[k], first[k + 1]).
  std::size_t first[shapes::kKinds + 1] = {};
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind) first[kind + 1] = first[kind] + shapes::count(scene, kind);
  std::vector<BuildPrim> prims(first[shapes::kKinds]);
  constexpr std::uint32_t kDropped = 0xFFFFFFFFu;
  auto makeRange = [&](std::size_t from, std::size_t to) {
    std::uint32_t kind = 0;
    for (std::size_t i = from; i < to; ++i) {
      while (i >= first[kind + 1]) ++kind;
      const std::uint32_t ref = gpu::primRef(kind, static_cast<std::uint32_t>(i - first[kind]));
      if (shapes::neverHit(scene, ref)) {
        prims[i].ref = kDropped;
        continue;
      }
      dvec3 lo, hi;
      shapes::bounds(scene, ref, lo, hi);
      prims[i] = makePrim((lo - origin) * scale, (hi - origin) * scale, ref);
    }
  };
  if (prims.size() >= kParallelBoxesMinPrims && threads > 1) {
    auto half = std::async(std::launch::async, makeRange, prims.size() / 2, prims.size());
    makeRange(0, prims.size() / 2);
    half.get();
  } else {
    makeRange(0, prims.size());
  }
  // Degenerate primitives (zero area, repeated or collinear vertices; zero radius or a
  // singular transform) can never be hit: they are left out, so neither backend tests them.
  std::erase_if(prims, [](const BuildPrim& p) { return p.ref == kDropped; });
  Bounds bounds;
  for (const BuildPrim& p : prims) bounds.add(p);

  Bvh bvh;
  // A binary tree with leaves of at least one primitive has at most 2n - 1 nodes.
  bvh.nodes.reserve(std::max<std::size_t>(1, 2 * prims.size()));
  bvh.nodes.emplace_back();
  Builder(prims, threads).build(bvh.nodes, 0, 0, static_cast<std::uint32_t>(prims.size()), 0, bounds, bvh.depth);
  bvh.primRefs.resize(prims.size());
  for (std::size_t i = 0; i < prims.size(); ++i) bvh.primRefs[i] = prims[i].ref;
  return bvh;
}

}  // namespace vkrt
