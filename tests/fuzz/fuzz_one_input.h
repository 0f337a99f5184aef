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

// Parses; a valid scene of modest size also goes through the BVH, flatten() and a tiny CPU
// render, so that what the parser lets through is exercised too. Scene errors are expected.
inline void oneInput(const std::uint8_t* data, std::size_t size) {
  SceneDesc scene;
  try {
    scene = parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.test");
  } catch (const SceneError&) {
    return;
  }
  if (scene.triangles.size() + scene.spheres.size() > 2000 || scene.lights.size() > 16) return;
  scene.width = std::min(scene.width, 6);
  scene.height = std::min(scene.height, 4);
  scene.maxDepth = std::min(scene.maxDepth, 3);
  (void)primitiveOffsets(scene);
  GpuScene flat = flatten(scene);
  CpuOptions options;
  options.threads = 1;
  (void)renderReference(scene, flat.bvh, options, nullptr);
}

}  // namespace vkrt::fuzz
