// The wide BVH (scene/wide_bvh.h, --bvh wide): the collapse keeps every leaf once, each child
// inside its node's box and the walk's stack within its bound; and the shaders walking it
// render what they render walking the binary one (both techniques, suspended or not).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "image/encode.h"
#include "render/progress.h"
#include "render/render.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "scene/wide_bvh.h"
#include "support/scene_generator.h"
#include "support/test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

bool inside(const gpu::GpuBvhNode& c, const gpu::GpuBvhNode& n) {
  return c.minX >= n.minX && c.minY >= n.minY && c.minZ >= n.minZ && c.maxX <= n.maxX && c.maxY <= n.maxY &&
         c.maxZ <= n.maxZ;
}

// Walks the wide tree from node `n` (its children's block): counts each leaf's primitive
// references, checks boxes, and returns the most entries a walk pushes from there down.
int walk(const Bvh& wide, const gpu::GpuBvhNode& n, std::map<std::uint32_t, int>& seen) {
  const std::uint32_t first = n.leftOrFirst;
  EXPECT_GE(first, 1u);
  EXPECT_LE(first + 4, wide.nodes.size());
  int used = 0, below = 0;
  for (std::uint32_t i = first; i < first + 4; ++i) {
    const gpu::GpuBvhNode& c = wide.nodes[i];
    if (c.primCount == 0 && c.leftOrFirst == 0) continue;   // unused
    ++used;
    EXPECT_TRUE(inside(c, n)) << "child " << i;
    if (c.primCount > 0) {
      for (std::uint32_t k = 0; k < c.primCount; ++k) ++seen[wide.primRefs[c.leftOrFirst + k]];
    } else {
      below = std::max(below, walk(wide, c, seen));
    }
  }
  EXPECT_GE(used, 2);
  return used - 1 + below;
}

void expectSoundCollapse(const Bvh& binary, int maxStack, int arity) {
  Bvh wide = binary;
  collapseToFourWide(wide, maxStack);
  EXPECT_TRUE(wide.wide);
  EXPECT_EQ(wide.primRefs, binary.primRefs);
  std::map<std::uint32_t, int> seen;
  int pushes = 0;
  if (wide.nodes[0].primCount == 0) {
    pushes = walk(wide, wide.nodes[0], seen);
  } else {
    for (std::uint32_t k = 0; k < wide.nodes[0].primCount; ++k) ++seen[wide.primRefs[k]];
  }
  EXPECT_EQ(seen.size(), binary.primRefs.size());
  for (const auto& [ref, times] : seen) EXPECT_EQ(times, 1) << "primRef " << ref;
  EXPECT_EQ(wide.depth + 1, pushes + 1) << "depth says the stack the walk needs";
  if (arity == 4) {
    EXPECT_LE(wide.depth + 1, maxStack);
    // Four children a node where the tree has them: at most 3/4 of the nodes of two a node
    // in blocks of four (1 + 2 (n - 1) for a binary tree of n; measured 0.53-0.55 here).
    if (binary.nodes.size() > 64) {
      EXPECT_LT(4 * wide.nodes.size(), 3 * (1 + 2 * (binary.nodes.size() - 1)));
    }
  } else {   // two a node: the binary tree in blocks, its stack as the binary walk's
    EXPECT_EQ(wide.nodes.size(), 1 + 2 * (binary.nodes.size() - 1));
    EXPECT_LE(wide.depth, binary.depth);
  }
}

TEST(WideBvh, KeepsEveryLeafOnceInsideItsBoxesWithinTheStack) {
  for (std::uint64_t seed : {1u, 4u, 9u, 23u, 40u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const SceneDesc scene = parseScene(difftest::generateScene(seed), "gen.test");
    const Bvh binary = buildBvh(scene);
    expectSoundCollapse(binary, static_cast<int>(gpu::kTraversalStackSize), 4);
    // A stack too small for four children a node: two, as the binary tree.
    if (binary.nodes[0].primCount == 0) expectSoundCollapse(binary, 1, 2);
  }
}

RadianceImage render(const std::string& path, bool wide, std::uint32_t stepBudget = 0, int width = 0,
                     int height = 0) {
  return renderFileQuietly(path, [&](RenderRequest& r) {
    r.wideBvh = wide;
    r.stepBudget = stepBudget;
    r.width = width;
    r.height = height;
  });
}

// Walking the wide tree finds the same nearest hits: the same image but where two hits are
// equally near (a tie, which the order of the walk breaks): at most 1 pixel in 2,000 more
// than 1/255 apart.
void expectSameImage(const std::string& name, const std::string& path, std::uint32_t stepBudget, int width = 0,
                     int height = 0) {
  const Image binary = encodeImage(render(path, false, 0, width, height), 1.0);
  const Image wide = encodeImage(render(path, true, stepBudget, width, height), 1.0);
  EXPECT_TRUE(imagesClose("wide-bvh-" + name, wide, binary, 1,
                          std::max<long long>(1, static_cast<long long>(binary.width) * binary.height / 2000)));
}

TEST(WideBvh, ShadersRenderWhatTheBinaryWalkRenders) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("wide-bvh");
  for (std::uint64_t seed : {2u, 7u, 31u}) {   // suspended every 3 steps, and the mirror halls among them
    writeFile(dir + "/g.test", difftest::generateScene(seed));
    expectSameImage("gen-" + std::to_string(seed), dir + "/g.test", 3);
  }
  const std::optional<std::string> course = cse167Dir();
  if (!course) GTEST_SKIP() << "no ../shared/cse167 (the course scenes); the generated scenes passed";
  for (const char* name : {"scene5", "scene6", "scene7"}) expectSameImage(name, *course + "/scenes/" + name + ".test", 0);
}

TEST(WideBvh, PathTracerRendersWhatTheBinaryWalkRenders) {
  if (!gpuContextOrSkip()) return;
  const std::optional<std::string> cse168 = cse168Dir();
  if (!cse168) GTEST_SKIP() << "no ../shared/cse168 (the path-tracing scenes)";
  expectSameImage("hw3-dragon", *cse168 + "/scenes/hw3/dragon.test", 5, 80, 60);
}

}  // namespace
