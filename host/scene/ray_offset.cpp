// The secondary-ray offset of every primitive (the policy: gpu_limits.h and doc/design.md, "The secondary-ray offsets").
#include "scene/ray_offset.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <future>
#include <limits>
#include <numeric>

#include "gpu_types.h"
#include "scene/shapes/shape.h"

namespace vkrt {
namespace {

// Scene bounds are measured on two threads from this many triangles on.
constexpr std::size_t kParallelMinTriangles = 50000;

struct Box {
  dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  void add(const dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void add(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool overlaps(const Box& b, double margin) const {
    return lo.x - margin <= b.hi.x && b.lo.x <= hi.x + margin && lo.y - margin <= b.hi.y && b.lo.y <= hi.y + margin &&
           lo.z - margin <= b.hi.z && b.lo.z <= hi.z + margin;
  }
  double diagonal() const { return lo.x <= hi.x ? glm::length(hi - lo) : 0.0; }
};

// The box of the primitive that `ref` refers to.
Box boxOf(const SceneDesc& scene, std::uint32_t ref) {
  Box b;
  shapes::bounds(scene, ref, b.lo, b.hi);
  return b;
}

// Union-find over triangles, with path halving.
struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Joins triangles that share a vertex position (exactly equal doubles), through an
// open-addressing table of corners (3 * triangle + k), the first corner seen at a position.
// The table starts at twice the triangle count (a closed mesh has about half as many
// positions as triangles) and doubles when half full (a soup of separate triangles has three
// times as many): a table sized for every corner (64 MB for a million triangles) spent most
// of its time in cache misses and in the kernel clearing its pages.
void joinSharedVertices(const std::vector<Triangle>& triangles, DisjointSets& sets) {
  constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
  struct Slot {
    std::uint32_t hash;            // the position's hash, checked before the position itself
    std::uint32_t corner = kEmpty;
  };
  auto corner = [&triangles](std::uint32_t c) -> const dvec3& { return triangles[c / 3].p[c % 3]; };
  auto hash = [](const dvec3& p) {
    std::uint64_t h = 0;
    for (int k = 0; k < 3; ++k) {
      double v = p[k] + 0.0;   // -0 and +0 alike
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
    }
    h ^= h >> 31;   // the finish of splitmix64: every bit reaches the low bits used as the slot
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  };
  std::size_t capacity = 16;
  while (capacity < 2 * triangles.size()) capacity *= 2;
  std::vector<Slot> table(capacity);
  std::size_t used = 0;
  // Puts a corner whose position is not in the table into the first free slot of its probe.
  auto place = [&](std::uint64_t h, std::uint32_t c) {
    std::size_t s = h & (capacity - 1);
    while (table[s].corner != kEmpty) s = (s + 1) & (capacity - 1);
    table[s] = {static_cast<std::uint32_t>(h >> 32), c};
  };
  // The hashes of the next kAhead corners are computed early and their slots prefetched: the
  // probes are cache misses, and this way several are under way at once.
  constexpr std::uint32_t kAhead = 16;
  std::uint64_t ahead[kAhead];
  const std::uint32_t corners = static_cast<std::uint32_t>(3 * triangles.size());
  auto prefetch = [&](std::uint32_t c) {
    ahead[c % kAhead] = hash(corner(c));
    __builtin_prefetch(&table[ahead[c % kAhead] & (capacity - 1)]);
  };
  for (std::uint32_t c = 0; c < std::min(kAhead, corners); ++c) prefetch(c);
  for (std::uint32_t c = 0; c < corners; ++c) {
    const dvec3& p = corner(c);
    const std::uint64_t h = ahead[c % kAhead];
    if (c + kAhead < corners) prefetch(c + kAhead);
    const std::uint32_t tag = static_cast<std::uint32_t>(h >> 32);
    for (std::size_t s = h & (capacity - 1);; s = (s + 1) & (capacity - 1)) {
      if (table[s].corner == kEmpty) {
        table[s] = {tag, c};
        if (++used * 2 > capacity) {   // half full: twice the slots, every position placed again
          std::vector<Slot> old(capacity * 2);
          old.swap(table);
          capacity *= 2;
          for (const Slot& slot : old)
            if (slot.corner != kEmpty) place(hash(corner(slot.corner)), slot.corner);
        }
        break;
      }
      if (table[s].hash == tag && corner(table[s].corner) == p) {
        sets.unite(table[s].corner / 3, c / 3);
        break;
      }
    }
  }
}

// A tree over boxes that answers "does any of them come within `margin` of this box?".
class BoxTree {
 public:
  explicit BoxTree(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
    if (boxes_.empty()) return;
    nodes_.resize(1);
    build(0, 0, boxes_.size());
  }
  bool anyNear(const Box& query, double margin) const {
    if (nodes_.empty()) return false;
    // Median splits: depth <= 32 for any count below 2^32, so the stack holds at most 33.
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!n.box.overlaps(query, margin)) continue;
      if (n.count > 0) {
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
          if (boxes_[i].overlaps(query, margin)) return true;
      } else {
        stack[top++] = n.first;
        stack[top++] = n.first + 1;
      }
    }
    return false;
  }

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0, count = 0;   // leaf: boxes [first, first + count); interior: children first, first + 1
  };
  // Fills node `index` with boxes [begin, end): median split on the longest axis.
  void build(std::uint32_t index, std::size_t begin, std::size_t end) {
    Box box;
    for (std::size_t i = begin; i < end; ++i) box.add(boxes_[i]);
    nodes_[index].box = box;
    if (end - begin <= 4) {
      nodes_[index].first = static_cast<std::uint32_t>(begin);
      nodes_[index].count = static_cast<std::uint32_t>(end - begin);
      return;
    }
    dvec3 extent = box.hi - box.lo;
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(boxes_.begin() + begin, boxes_.begin() + mid, boxes_.begin() + end,
                     [axis](const Box& a, const Box& b) { return a.lo[axis] + a.hi[axis] < b.lo[axis] + b.hi[axis]; });
    std::uint32_t children = static_cast<std::uint32_t>(nodes_.size());
    nodes_.resize(children + 2);
    nodes_[index].first = children;
    build(children, begin, mid);
    build(children + 1, mid, end);
  }
  std::vector<Box> boxes_;
  std::vector<Node> nodes_;
};

}  // namespace

bool sceneBounds(const SceneDesc& scene, dvec3& boxLo, dvec3& boxHi) {
  auto trianglesBox = [&scene](std::size_t begin, std::size_t end) {
    Box b;
    for (std::size_t i = begin; i < end; ++i) b.add(boxOf(scene, gpu::primRef(gpu::kPrimTriangle, static_cast<std::uint32_t>(i))));
    return b;
  };
  // Many triangles: the second half on another thread.
  const std::size_t nt = scene.triangles.size(), half = nt >= kParallelMinTriangles ? nt / 2 : nt;
  std::future<Box> second;
  if (half < nt) second = std::async(std::launch::async, trianglesBox, half, nt);
  Box box = trianglesBox(0, half);
  if (second.valid()) box.add(second.get());
  for (std::uint32_t kind = gpu::kPrimTriangle + 1; kind < shapes::kKinds; ++kind)
    for (std::uint32_t i = 0; i < shapes::count(scene, kind); ++i) box.add(boxOf(scene, gpu::primRef(kind, i)));
  if (!(box.lo.x <= box.hi.x)) return false;
  boxLo = box.lo;
  boxHi = box.hi;
  return true;
}

namespace {

// The distance from p to box [lo, hi] (0 inside it).
double boxDistance(const dvec3& p, const dvec3& lo, const dvec3& hi) {
  return glm::length(glm::max(glm::max(lo - p, p - hi), dvec3(0.0)));
}

// Whether some primitive comes within `reach` of p.
bool geometryWithin(const SceneDesc& scene, const dvec3& p, double reach) {
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind)
    for (std::uint32_t i = 0; i < shapes::count(scene, kind); ++i) {
      const std::uint32_t ref = gpu::primRef(kind, i);
      const Box box = boxOf(scene, ref);
      if (boxDistance(p, box.lo, box.hi) > reach) continue;
      if (shapes::within(scene, ref, p, reach)) return true;
    }
  return false;
}

double maxNorm(const dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

dvec3 floatFrameOrigin(const SceneDesc& scene) {
  dvec3 lo, hi;
  if (!sceneBounds(scene, lo, hi)) return scene.camera.from;
  const dvec3 centre = 0.5 * lo + 0.5 * hi;   // (halves first: no overflow near the largest double)
  // The centre of the geometry, unless the camera is much nearer to some geometry than to the
  // centre (a far object widens the box): float32 would then round what the camera sees
  // nearby more coarsely than its distance allows, and the frame is centred on the camera.
  const double fromCentre = glm::length(scene.camera.from - centre);
  if (!(fromCentre > 0.0) || !std::isfinite(fromCentre)) return fromCentre > 0.0 ? scene.camera.from : centre;
  return geometryWithin(scene, scene.camera.from, fromCentre * kFrameCentreReach) ? scene.camera.from : centre;
}

double floatFrameScale(const SceneDesc& scene, const dvec3& origin) {
  dvec3 lo, hi;
  double extent = maxNorm(scene.camera.from - origin);
  if (sceneBounds(scene, lo, hi)) extent = std::max({extent, maxNorm(lo - origin), maxNorm(hi - origin)});
  if (!(extent > 0.0) || !std::isfinite(extent)) return 1.0;
  if (extent >= kFrameExtentLow && extent <= kFrameExtentHigh) return 1.0;
  return std::ldexp(1.0, std::clamp(-std::ilogb(extent), -1000, 1000));   // the extent into [1, 2)
}

double offsetForSize(double size) {
  const double base = gpu::kSecondaryRayTMin;
  if (!(size > 0.0) || !std::isfinite(size)) return base;
  // Whole decades away from the course's sizes: 0 for the course's objects (their images stay
  // as they were), and exactly k under scaling by 10^k.
  double decades = 0.0;
  if (size < gpu::kCourseSizeLow) decades = -std::ceil(std::log10(gpu::kCourseSizeLow / size));
  if (size > gpu::kCourseSizeHigh) decades = std::ceil(std::log10(size / gpu::kCourseSizeHigh));
  return base * std::pow(10.0, decades);
}

PrimitiveOffsets primitiveOffsets(const SceneDesc& scene) {
  const std::size_t nt = scene.triangles.size();
  PrimitiveOffsets result;
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind) result.ofKind(kind).resize(shapes::count(scene, kind));
  auto triangleRef = [](std::size_t i) { return gpu::primRef(gpu::kPrimTriangle, static_cast<std::uint32_t>(i)); };

  // Objects: connected triangles, and each primitive of another kind (a sphere). Their boxes
  // and sizes.
  DisjointSets sets(nt);
  joinSharedVertices(scene.triangles, sets);
  std::vector<std::uint32_t> objectOf(nt);
  std::vector<Box> objectBoxes;
  std::vector<std::uint32_t> objectOfRoot(nt, 0xFFFFFFFFu);
  for (std::uint32_t i = 0; i < nt; ++i) {
    std::uint32_t root = sets.find(i);
    if (objectOfRoot[root] == 0xFFFFFFFFu) {
      objectOfRoot[root] = static_cast<std::uint32_t>(objectBoxes.size());
      objectBoxes.emplace_back();
    }
    objectOf[i] = objectOfRoot[root];
    objectBoxes[objectOf[i]].add(boxOf(scene, triangleRef(i)));
  }
  // The other kinds' objects follow, kind by kind: primitive i of `kind` is object
  // firstObject[kind] + i.
  std::size_t firstObject[shapes::kKinds] = {};
  for (std::uint32_t kind = gpu::kPrimTriangle + 1; kind < shapes::kKinds; ++kind) {
    firstObject[kind] = objectBoxes.size();
    for (std::uint32_t i = 0; i < shapes::count(scene, kind); ++i) objectBoxes.push_back(boxOf(scene, gpu::primRef(kind, i)));
  }
  result.objects = static_cast<int>(objectBoxes.size());

  // Each primitive starts from its own object's offset.
  std::vector<double> objectOffset(objectBoxes.size());
  for (std::size_t o = 0; o < objectBoxes.size(); ++o) objectOffset[o] = offsetForSize(objectBoxes[o].diagonal());
  for (std::size_t i = 0; i < nt; ++i) result.triangles[i] = objectOffset[objectOf[i]];
  for (std::uint32_t kind = gpu::kPrimTriangle + 1; kind < shapes::kKinds; ++kind)
    for (std::size_t i = 0; i < result.ofKind(kind).size(); ++i) result.ofKind(kind)[i] = objectOffset[firstObject[kind] + i];

  // Then takes the smallest offset of the objects within its own offset's reach: a ray from
  // it ignores hits closer than that, and theirs must not be ignored beyond their own offset.
  std::vector<double> levels(objectOffset);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {   // the largest level lowers nothing
    std::vector<Box> boxes;
    for (std::size_t o = 0; o < objectBoxes.size(); ++o)
      if (objectOffset[o] == levels[l]) boxes.push_back(objectBoxes[o]);
    BoxTree tree(std::move(boxes));
    auto lower = [&](double& offset, double own, const Box& box) {
      if (offset > levels[l] && tree.anyNear(box, own)) offset = levels[l];
    };
    for (std::size_t i = 0; i < nt; ++i) lower(result.triangles[i], objectOffset[objectOf[i]], boxOf(scene, triangleRef(i)));
    for (std::uint32_t kind = gpu::kPrimTriangle + 1; kind < shapes::kKinds; ++kind)
      for (std::size_t i = 0; i < result.ofKind(kind).size(); ++i) {
        const std::size_t o = firstObject[kind] + i;
        lower(result.ofKind(kind)[i], objectOffset[o], objectBoxes[o]);
      }
  }
  return result;
}

SecondaryRayOffsets secondaryRayOffsets(double primitiveOffset, const dvec3& pFromOrigin, const dvec3& pFromCamera) {
  double magnitude = std::max({std::abs(pFromOrigin.x), std::abs(pFromOrigin.y), std::abs(pFromOrigin.z),
                               std::abs(pFromCamera.x), std::abs(pFromCamera.y), std::abs(pFromCamera.z)});
  return {std::max(primitiveOffset, double{gpu::kOffsetPerMagnitude} * magnitude),
          double{gpu::kGrazingPerMagnitude} * magnitude};
}

}  // namespace vkrt
