// Differential checks of one scene (differential.h).
#include "differential.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <map>
#include <optional>

#include "cpu/reference.h"
#include "gpu/vulkan_renderer.h"
#include "compare/image_diff.h"
#include "image/encode.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "scene_generator.h"

namespace vkrt::difftest {

const char* checkLetter(Check c) {
  switch (c) {
    case kBackends: return "a";
    case kCutoff: return "b";
    case kMetamorphic: return "c";
    case kGround: return "d";
    default: return "?";
  }
}

const char* checkName(Check c) {
  switch (c) {
    case kBackends: return "backends";
    case kCutoff: return "cutoff";
    case kMetamorphic: return "metamorphic";
    case kGround: return "ground";
    default: return "?";
  }
}

long long allowedFlips(int width, int height) {
  return std::max<long long>(3, static_cast<long long>(width) * height / 1000);
}

bool Outcome::passed(Check c) const {
  for (const Comparison& cmp : comparisons)
    if (cmp.check == c && !cmp.passed()) return false;
  for (const auto& [check, what] : problems)
    if (check == c) return false;
  return true;
}

bool Outcome::passed() const {
  for (Check c : {kBackends, kCutoff, kMetamorphic, kGround})
    if (!passed(c)) return false;
  return true;
}

std::uint32_t stepBudgetForSeed(std::uint64_t seed) { return seed % 2 == 0 ? 3u : 7u; }

std::uint32_t stepBudgetOfText(const std::string& text) {
  const std::string key = "# difftest-step-budget:";
  std::size_t at = text.find(key);
  if (at == std::string::npos) return 3;
  long v = std::strtol(text.c_str() + at + key.size(), nullptr, 10);
  return v > 0 ? static_cast<std::uint32_t>(v) : 3u;
}

long long metamorphicFlipsOfText(const std::string& text, long long standard) {
  const std::string key = "# difftest-metamorphic-flips:";
  std::size_t at = text.find(key);
  if (at == std::string::npos) return standard;
  long v = std::strtol(text.c_str() + at + key.size(), nullptr, 10);
  return v > standard ? v : standard;
}

namespace {

struct VulkanSetting {
  Cutoff cutoff = Cutoff::Off;
  std::uint32_t stepBudget = 0;   // 0: the default
  bool operator<(const VulkanSetting& o) const {
    return std::pair(int(cutoff), stepBudget) < std::pair(int(o.cutoff), o.stepBudget);
  }
};

std::string settingLabel(const VulkanSetting& s) {
  std::string label = std::string("vulkan-cutoff-") + (s.cutoff == Cutoff::On ? "on" : "off");
  if (s.stepBudget) label += "-budget" + std::to_string(s.stepBudget);
  return label;
}

// Renders one scene text with either backend, each image once.
class Renders {
 public:
  Renders(const CheckOptions& options, Outcome& outcome) : options_(options), outcome_(outcome) {}

  // The parsed scene, or nothing (a problem of `check` recorded) when it does not parse.
  const SceneDesc* scene(const std::string& text, const std::string& name, Check check) {
    auto it = scenes_.find(text);
    if (it == scenes_.end()) {
      std::optional<SceneDesc> parsed;
      try {
        parsed = parseScene(text, name);
      } catch (const std::exception& e) {
        parseErrors_[text] = e.what();
      }
      it = scenes_.emplace(text, std::move(parsed)).first;
    }
    if (!it->second) outcome_.problems.emplace_back(check, name + " does not parse: " + parseErrors_[text]);
    return it->second ? &*it->second : nullptr;
  }

  const Image* cpu(const std::string& text, const std::string& name, Check check) {
    auto key = std::pair(text, std::string("cpu"));
    if (auto it = images_.find(key); it != images_.end()) return it->second ? &*it->second : nullptr;
    std::optional<Image> image;
    if (const SceneDesc* s = scene(text, name, check)) {
      try {
        RayCounts rays;
        CpuOptions cpu;
        cpu.threads = options_.cpuThreads;
        image = encodeImage(renderReference(*s, buildBvh(*s), cpu, &rays), 1.0);
        if (rays.nonFinite)
          outcome_.problems.emplace_back(check, name + ": the CPU reference produced " +
                                                    std::to_string(rays.nonFinite) + " NaN or infinite pixels");
      } catch (const std::exception& e) {
        outcome_.problems.emplace_back(check, name + ": the CPU reference failed: " + e.what());
      }
    }
    images_[key] = std::move(image);
    return images_[key] ? &*images_[key] : nullptr;
  }

  const Image* vulkan(const std::string& text, const std::string& name, VulkanSetting setting, Check check) {
    auto key = std::pair(text, settingLabel(setting));
    if (auto it = images_.find(key); it != images_.end()) return it->second ? &*it->second : nullptr;
    std::optional<Image> image;
    if (const SceneDesc* s = scene(text, name, check)) {
      Context& context = *options_.context;
      try {
        VulkanOptions vk;
        vk.cutoff = setting.cutoff;
        vk.stepBudget = setting.stepBudget;
        RayCounts rays;
        VulkanTimings timings;
        int before = context.validationMessages();
        image = encodeImage(renderVulkan(context, flatten(*s), vk, &rays, &timings), 1.0);
        if (rays.nonFinite)
          outcome_.problems.emplace_back(check, name + " (" + key.second + "): the shader produced " +
                                                    std::to_string(rays.nonFinite) + " NaN or infinite pixels");
        if (context.validationMessages() != before)
          outcome_.problems.emplace_back(check, name + " (" + key.second +
                                                    "): the Vulkan validation layer reported problems (see stderr)");
        suspensions_[key] = timings.suspensions;
      } catch (const std::exception& e) {
        outcome_.problems.emplace_back(check, name + " (" + key.second + "): the Vulkan backend failed: " + e.what());
      }
    }
    images_[key] = std::move(image);
    return images_[key] ? &*images_[key] : nullptr;
  }

  std::uint64_t suspensions(const std::string& text, VulkanSetting setting) const {
    auto it = suspensions_.find(std::pair(text, settingLabel(setting)));
    return it == suspensions_.end() ? 0 : it->second;
  }

 private:
  const CheckOptions& options_;
  Outcome& outcome_;
  std::map<std::string, std::optional<SceneDesc>> scenes_;
  std::map<std::string, std::string> parseErrors_;
  std::map<std::pair<std::string, std::string>, std::optional<Image>> images_;
  std::map<std::pair<std::string, std::string>, std::uint64_t> suspensions_;
};

void compareInto(Outcome& outcome, Check check, std::string name, std::string actualLabel, const Image* actual,
                 std::string expectedLabel, const Image* expected, int stepTolerance, long long allowed,
                 std::string variantText = "") {
  if (!actual || !expected) return;   // the failed render is already a problem
  Comparison c;
  c.check = check;
  c.name = std::move(name);
  c.actualLabel = std::move(actualLabel);
  c.expectedLabel = std::move(expectedLabel);
  c.actual = *actual;
  c.expected = *expected;
  c.stepTolerance = stepTolerance;
  c.allowedOver = allowed;
  c.variantText = std::move(variantText);
  if (actual->width != expected->width || actual->height != expected->height) {
    c.over = static_cast<long long>(expected->width) * expected->height + 1;
    c.worst = "the sizes differ";
  } else {
    ImageDiff d = compare(*actual, *expected);
    c.over = d.countOver(stepTolerance);
    c.maxDiff = d.maxChannelDiff;
    c.worst = d.worst(5);
  }
  outcome.comparisons.push_back(std::move(c));
}

}  // namespace

Outcome runChecks(const std::string& text, const std::string& name, const CheckOptions& options) {
  Outcome outcome;
  Renders renders(options, outcome);
  const bool gpu = options.context != nullptr;
  if (!gpu) outcome.notes.push_back("no Vulkan device: the Vulkan renders are left out");
  const SceneDesc* base = renders.scene(text, name, kBackends);
  if (!base) {
    for (Check c : {kCutoff, kMetamorphic, kGround})
      if (options.checks & c) outcome.problems.emplace_back(c, name + " does not parse");
    return outcome;
  }
  const long long flips = allowedFlips(base->width, base->height);
  const VulkanSetting off{Cutoff::Off, 0};

  // a. Vulkan against the CPU reference.
  if ((options.checks & kBackends) && gpu)
    compareInto(outcome, kBackends, "vulkan-vs-cpu", "vulkan", renders.vulkan(text, name, off, kBackends), "cpu",
                renders.cpu(text, name, kBackends), kFlipStepTolerance, flips);

  // b. The cut-off and the suspension of pixels change no pixel.
  if ((options.checks & kCutoff) && gpu) {
    const Image* exact = renders.vulkan(text, name, off, kCutoff);
    const std::uint32_t budget = options.stepBudget;
    for (VulkanSetting s : {VulkanSetting{Cutoff::On, 0}, VulkanSetting{Cutoff::On, budget},
                            VulkanSetting{Cutoff::Off, budget}}) {
      std::string label = settingLabel(s);
      compareInto(outcome, kCutoff, label.substr(7) + "-vs-cutoff-off", label, renders.vulkan(text, name, s, kCutoff),
                  settingLabel(off), exact, 0, 0);
    }
    if (renders.suspensions(text, {Cutoff::Off, budget}) == 0)
      outcome.notes.push_back("check b: no pixel was suspended with step budget " + std::to_string(budget));
  }

  // c. The same picture at another scale and place.
  if (options.checks & kMetamorphic) {
    const long long metamorphicFlips = metamorphicFlipsOfText(text, flips);
    struct Variant {
      const char* name;
      double k;
      dvec3 offset;
    };
    for (const Variant& v : {Variant{"x1e-3", 1e-3, dvec3(0.0)}, Variant{"x1e4", 1e4, dvec3(0.0)},
                             Variant{"moved1e4", 1.0, dvec3(1e4)}}) {
      std::string moved = scaledAndMoved(text, v.k, v.offset);
      std::string movedName = name + " " + v.name;
      compareInto(outcome, kMetamorphic, std::string("cpu-") + v.name, std::string("cpu-") + v.name,
                  renders.cpu(moved, movedName, kMetamorphic), "cpu", renders.cpu(text, name, kMetamorphic),
                  kFlipStepTolerance, metamorphicFlips, moved);
      if (gpu)
        compareInto(outcome, kMetamorphic, std::string("vulkan-") + v.name, std::string("vulkan-") + v.name,
                    renders.vulkan(moved, movedName, off, kMetamorphic), "vulkan",
                    renders.vulkan(text, name, off, kMetamorphic), kFlipStepTolerance, metamorphicFlips, moved);
    }
  }

  // d. A vast black ground just below everything changes nothing.
  if (options.checks & kGround) {
    std::optional<std::string> grounded = withVastBlackGround(text, *base);
    if (!grounded) {
      outcome.notes.push_back("check d left out: directional lights on every side");
    } else {
      std::string groundedName = name + " with a vast black ground";
      compareInto(outcome, kGround, "cpu-ground", "cpu-ground", renders.cpu(*grounded, groundedName, kGround), "cpu",
                  renders.cpu(text, name, kGround), kFlipStepTolerance, flips, *grounded);
      if (gpu)
        compareInto(outcome, kGround, "vulkan-ground", "vulkan-ground",
                    renders.vulkan(*grounded, groundedName, off, kGround), "vulkan",
                    renders.vulkan(text, name, off, kGround), kFlipStepTolerance, flips, *grounded);
    }
  }
  return outcome;
}

}  // namespace vkrt::difftest
