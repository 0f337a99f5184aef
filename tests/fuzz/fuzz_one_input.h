// What the parser fuzzer does with one input, shared by the libFuzzer target
// (tests/fuzz/parse_fuzzer.cpp) and the regression test that replays every input that ever
// crashed it (tests/fuzz/regressions/, run by fuzz_regression_test.cpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cpu/reference.h"
#include "scene/bvh.h"
#include "scene/diagnostic.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "scene/ray_offset.h"

namespace vkrt::fuzz {

// The most work one input may cost the CPU render, in ray-primitive tests: a pixel traces at
// most maxdepth + 1 segments, each with a shadow ray per light, and a ray tests at worst every
// primitive (when all of them lie across its path). This much takes about a second under the
// sanitizers (measured with 1,000 copies of each of two facing mirrors: doc/robustness.md, "Fuzzing").
constexpr std::uint64_t kMaxWork = 30'000'000;

// Parses; a valid scene of modest size then goes where vkrt takes it: flatten() (what the
// Vulkan backend uploads) and the CPU backend, rendered as `vkrt --backend cpu` renders it
// (the world-space BVH of buildBvh, the scene's own maxdepth), on an image of a few pixels.
// Scene errors are expected.
inline void oneInput(const std::uint8_t* data, std::size_t size) {
  SceneDesc scene;
  try {
    scene = parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.test");
  } catch (const SceneError&) {
    return;
  }
  if (scene.triangles.size() + scene.spheres.size() > 2000 || scene.lights.size() > 16) return;
  // The cost bound: at most 6x4 pixels, a single one when the scene's maxdepth, lights and
  // primitives make that many too costly, and no render when even one pixel could be. The
  // maxdepth is never lowered: deep mirror chains are what users run, and the loop must take
  // them (maxdepth 1,000,000 between two mirrors with a few lights is rendered).
  const std::uint64_t workPerPixel = (static_cast<std::uint64_t>(scene.maxDepth) + 1) * (scene.lights.size() + 1) *
                                     (scene.triangles.size() + scene.spheres.size() + 1);
  scene.width = std::min(scene.width, 6);
  scene.height = std::min(scene.height, 4);
  if (workPerPixel * static_cast<std::uint64_t>(scene.width * scene.height) > kMaxWork) scene.width = scene.height = 1;
  (void)primitiveOffsets(scene);
  (void)flatten(scene);
  if (workPerPixel > kMaxWork) return;
  Bvh bvh = buildBvh(scene);
  CpuOptions options;
  options.threads = 1;
  (void)renderReference(scene, bvh, options, nullptr);
}

}  // namespace vkrt::fuzz
