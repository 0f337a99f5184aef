// Collapsing the binary BVH into blocks of four children.
#include "scene/wide_bvh.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace vkrt {
namespace {

float area(const gpu::GpuBvhNode& n) {
  const float x = n.maxX - n.minX, y = n.maxY - n.minY, z = n.maxZ - n.minZ;
  return x < 0.0f ? 0.0f : x * y + y * z + z * x;
}

class Collapse {
 public:
  Collapse(const std::vector<gpu::GpuBvhNode>& binary, std::size_t arity) : in_(binary), arity_(arity) {}

  // The wide tree: the root, then the blocks; the most a walk's stack holds.
  std::vector<gpu::GpuBvhNode> run(int& stackEntries) {
    out_.clear();
    out_.reserve(in_.size() * 2);
    out_.push_back(in_[0]);
    int pushes = 0;
    if (in_[0].primCount == 0) out_[0].leftOrFirst = block(0, pushes);
    stackEntries = pushes + 1;
    return std::move(out_);
  }

 private:
  // Emits the block of interior binary node `b`'s children (its own, or the largest below
  // it); returns the block's index, and in `pushes` the most entries a walk pushes from it down.
  std::uint32_t block(std::uint32_t b, int& pushes) {
    std::vector<std::uint32_t> children = {in_[b].leftOrFirst, in_[b].leftOrFirst + 1};
    while (children.size() < arity_) {
      // The largest interior child opens into its two (in its place: the order stays the tree's).
      std::size_t pick = children.size();
      for (std::size_t i = 0; i < children.size(); ++i)
        if (in_[children[i]].primCount == 0 && (pick == children.size() || area(in_[children[i]]) > area(in_[children[pick]])))
          pick = i;
      if (pick == children.size()) break;
      const std::uint32_t left = in_[children[pick]].leftOrFirst;
      children[pick] = left;
      children.insert(children.begin() + static_cast<std::ptrdiff_t>(pick) + 1, left + 1);
    }
    const auto first = static_cast<std::uint32_t>(out_.size());
    out_.resize(out_.size() + 4, gpu::GpuBvhNode{});   // unused: primCount 0, leftOrFirst 0
    int below = 0;
    for (std::size_t i = 0; i < children.size(); ++i) {
      out_[first + i] = in_[children[i]];
      if (in_[children[i]].primCount > 0) continue;
      int childPushes = 0;
      const std::uint32_t at = block(children[i], childPushes);
      out_[first + i].leftOrFirst = at;
      below = std::max(below, childPushes);
    }
    pushes = static_cast<int>(children.size()) - 1 + below;
    return first;
  }

  const std::vector<gpu::GpuBvhNode>& in_;
  std::size_t arity_;
  std::vector<gpu::GpuBvhNode> out_;
};

}  // namespace

void collapseToFourWide(Bvh& binary, int maxStackEntries) {
  int entries = 0;
  std::vector<gpu::GpuBvhNode> wide = Collapse(binary.nodes, 4).run(entries);
  if (entries > maxStackEntries) wide = Collapse(binary.nodes, 2).run(entries);
  binary.nodes = std::move(wide);
  binary.depth = entries - 1;
  binary.wide = true;
}

}  // namespace vkrt
