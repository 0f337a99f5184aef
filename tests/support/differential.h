// Differential checks of one scene (text): the Vulkan backend against the CPU reference, the
// exactness cut-off and pixel suspension against neither, and the scene against itself scaled,
// moved, or with a vast black ground added. Used by tests/differential_test.cpp and by the
// vkrt_difftest tool; knows nothing of gtest.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "image/image.h"

namespace vkrt::difftest {

// The checks, by letter.
enum Check : unsigned {
  kBackends = 1u,      // a: the Vulkan backend (cut-off off) against the CPU reference
  kCutoff = 2u,        // b: cut-off on against off, and with a small step budget: bit for bit
  kMetamorphic = 4u,   // c: the scene x1e-3, x1e4 and moved by 1e4 against itself (both backends)
  kGround = 8u,        // d: the scene with a vast black ground just below everything against itself
  kAllChecks = 15u,
};
const char* checkLetter(Check c);   // "a" ... "d"
const char* checkName(Check c);     // "backends", "cutoff", "metamorphic", "ground"

// Tolerances. Checks a, c and d compare renders that round differently (float32 against
// double, or the same scene in other coordinates): a silhouette or shadow-edge pixel may flip
// between hit and miss, so at most 0.1% of the pixels (and at least 3) may differ by more than
// 2/255; the tolerance of the other GPU-against-CPU tests. Check b compares renders that
// must be identical by construction: no pixel may differ at all.
inline constexpr int kFlipStepTolerance = 2;
long long allowedFlips(int width, int height);   // max(3, pixels / 1000)

// One comparison of two images.
struct Comparison {
  Check check = kBackends;
  std::string name;            // e.g. "cutoff-on-budget3-vs-off"; a file-name-safe word
  std::string actualLabel, expectedLabel;
  Image actual, expected;
  int stepTolerance = 0;       // in 8-bit steps
  long long allowedOver = 0;   // pixels allowed over stepTolerance
  long long over = 0;          // pixels over stepTolerance
  int maxDiff = 0;             // largest channel difference, 8-bit steps
  std::string worst;           // the five worst pixels
  std::string variantText;     // the rewritten scene, for checks c and d
  bool passed() const { return over <= allowedOver; }
};

struct Outcome {
  std::vector<Comparison> comparisons;
  // Failures that are not image differences: a render that threw, NaN or infinite colours, a
  // validation-layer message. Each names its check.
  std::vector<std::pair<Check, std::string>> problems;
  std::vector<std::string> notes;   // checks left out, and why
  bool passed(Check c) const;
  bool passed() const;
};

struct CheckOptions {
  unsigned checks = kAllChecks;
  std::uint32_t stepBudget = 3;   // for check b: steps per pixel per dispatch
  Context* context = nullptr;     // the Vulkan checks are left out without one
  int cpuThreads = 0;             // 0: every hardware thread
};

// Parses and renders `text` (its name used in messages) and runs the chosen checks. A scene
// that does not parse is a problem of every chosen check.
Outcome runChecks(const std::string& text, const std::string& name, const CheckOptions& options);

// The step budget for a seed's check b: 3 or 7, alternately.
std::uint32_t stepBudgetForSeed(std::uint64_t seed);

// The step budget a regression scene asks for in a line `# difftest-step-budget: N`, or 3.
std::uint32_t stepBudgetOfText(const std::string& text);

// Check c's allowance for a regression scene that documents a known limit of the offset
// policy under scaling (`# difftest-metamorphic-flips: N`, its reason stated beside it), or
// `standard`; never less than `standard`.
long long metamorphicFlipsOfText(const std::string& text, long long standard);

}  // namespace vkrt::difftest
