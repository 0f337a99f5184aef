// The GPU's BVH: the binary binned-SAH tree (bvh.h) collapsed into one of four children a
// node, which the shaders walk with fewer steps (traverse.glsl). Same node struct, same leaves.
#pragma once

#include "scene/bvh.h"

namespace vkrt {

// Collapses `binary` in place: nodes[0] is the root (its box; a leaf stays a leaf); an
// interior node's leftOrFirst is the first of its block of 4 adjacent child nodes, of which
// the unused ones have primCount 0 and leftOrFirst 0 (a stack entry of 0, which no child has:
// blocks start at 1). Each interior node takes the four largest (by surface area) of the
// binary nodes below it. depth becomes the wide walk's: depth + 1 is the most entries its
// stack holds (the children a node pushes, 3 at most, summed along a path, and 1). Where that
// would exceed `maxStackEntries` the children are the binary ones (2 of each block).
void collapseToFourWide(Bvh& binary, int maxStackEntries = static_cast<int>(gpu::kTraversalStackSize));

}  // namespace vkrt
