// Bounding volume hierarchy over a scene's triangles and spheres, built on the host with a
// binned surface-area heuristic. Both backends traverse it; neither shares intersection code.
#pragma once

#include <cstdint>
#include <vector>

#include "gpu_types.h"
#include "scene/scene_desc.h"

namespace vkrt {

// Traversal stacks of this many entries never overflow (the builder bounds the depth). The
// shaders' stacks, and the ones they save when suspended, hold kTraversalStackSize entries.
inline constexpr int kMaxBvhDepth = 96;
static_assert(kMaxBvhDepth <= static_cast<int>(gpu::kTraversalStackSize),
              "a BVH this deep overflows the shaders' traversal stacks");

struct Bvh {
  // nodes[0] is the root. An interior node's children are adjacent (left, left + 1).
  std::vector<gpu::GpuBvhNode> nodes;
  // Leaf contents: primRef(kind, index) (a triangle's is its index).
  std::vector<std::uint32_t> primRefs;
  // Levels of the tree (1 for a lone root); a traversal stack needs at most depth + 1 entries.
  int depth = 1;
  // Interior nodes hold blocks of four children (scene/wide_bvh.h), not pairs.
  bool wide = false;
};

// Builds the hierarchy over the primitives that can be hit (degenerate ones are left out).
// An empty scene gives one empty leaf whose box contains nothing.
// The boxes are of the geometry moved by -origin, then multiplied by `scale` (flatten() builds
// for its float32 frame; the CPU reference for world coordinates). Builds on up to `threads`
// threads (0: one per core); the tree is the same for every count.
Bvh buildBvh(const SceneDesc& scene, const dvec3& origin = dvec3(0.0), int threads = 0, double scale = 1.0);

// Throws OutOfMemory for a scene of more primitives of one kind than a primitive reference can
// index (2^29; gpu_types.h, primRef). buildBvh checks it first; flatten before anything else.
void checkPrimitiveCounts(const SceneDesc& scene);

}  // namespace vkrt
