// vkrt_difftest: differential testing by hand, over many random scenes (scene_generator.h)
// or given scene files. Prints a summary; writes each disagreement's scene, images and an
// amplified difference image to an output directory.
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "differential.h"
#include "gpu/context.h"
#include "gpu/device_error.h"
#include "compare/image_diff.h"
#include "image/png.h"
#include "scene_generator.h"

using namespace vkrt;
using namespace vkrt::difftest;
namespace fs = std::filesystem;

namespace {

const char* kUsage =
    "usage: vkrt_difftest [--seeds A..B | --seeds N] [--scene FILE]... [options]\n"
    "  --seeds A..B     generated scenes of seeds A to B (both included); default 1..100\n"
    "  --scene FILE     a scene file instead (repeatable; step budget from '# difftest-step-budget: N')\n"
    "  --checks abcd    which checks: a backends, b cut-off and suspension, c scaled and moved, d vast ground\n"
    "  --budget N       step budget of check b (default: 3 or 7 by seed)\n"
    "  --out DIR        where disagreements are written (default difftest-out)\n"
    "  --cpu-only       no Vulkan device: the CPU halves of checks c and d only\n"
    "  --validation     enable the Vulkan validation layer (slower)\n"
    "  --print SEED     print the scene of SEED and exit\n"
    "  -v               one line per scene\n";

struct Job {
  std::string name;     // "seed 17" or the file
  std::string dirName;  // "seed-17" or the file's stem
  std::string text;
  std::uint32_t budget;
  std::uint64_t seed = 0;
  bool generated = false;
};

std::string fileName(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return out;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t first = 1, last = 100;
  std::vector<std::string> files;
  unsigned checks = kAllChecks;
  std::uint32_t budget = 0;
  std::string outDir = "difftest-out";
  bool cpuOnly = false, validation = false, verbose = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "error: %s needs a value\n%s", a.c_str(), kUsage);
        std::exit(1);
      }
      return argv[++i];
    };
    if (a == "--seeds") {
      std::string v = value();
      std::size_t dots = v.find("..");
      first = std::strtoull(v.c_str(), nullptr, 10);
      last = dots == std::string::npos ? first : std::strtoull(v.c_str() + dots + 2, nullptr, 10);
    } else if (a == "--scene") {
      files.push_back(value());
    } else if (a == "--checks") {
      checks = 0;
      for (char c : value()) {
        if (c < 'a' || c > 'd') {
          std::fprintf(stderr, "error: --checks takes letters a to d\n%s", kUsage);
          return 1;
        }
        checks |= 1u << (c - 'a');
      }
    } else if (a == "--budget") {
      budget = static_cast<std::uint32_t>(std::strtoul(value().c_str(), nullptr, 10));
    } else if (a == "--out") {
      outDir = value();
    } else if (a == "--cpu-only") {
      cpuOnly = true;
    } else if (a == "--validation") {
      validation = true;
    } else if (a == "--print") {
      std::fputs(generateScene(std::strtoull(value().c_str(), nullptr, 10)).c_str(), stdout);
      return 0;
    } else if (a == "-v") {
      verbose = true;
    } else if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else {
      std::fprintf(stderr, "error: unknown argument '%s'\n%s", a.c_str(), kUsage);
      return 1;
    }
  }

  std::vector<Job> jobs;
  if (files.empty()) {
    for (std::uint64_t s = first; s <= last; ++s) {
      Job j;
      j.seed = s;
      j.generated = true;
      j.name = "seed " + std::to_string(s);
      j.dirName = "seed-" + std::to_string(s);
      j.text = generateScene(s);
      j.budget = budget ? budget : stepBudgetForSeed(s);
      jobs.push_back(std::move(j));
    }
  } else {
    for (const std::string& f : files) {
      std::ifstream in(f, std::ios::binary);
      if (!in) {
        std::fprintf(stderr, "error: cannot read %s\n", f.c_str());
        return 4;
      }
      std::ostringstream s;
      s << in.rdbuf();
      Job j;
      j.name = f;
      j.dirName = fileName(fs::path(f).stem().string());
      j.text = s.str();
      j.budget = budget ? budget : stepBudgetOfText(j.text);
      jobs.push_back(std::move(j));
    }
  }

  std::unique_ptr<Context> context;
  if (!cpuOnly) {
    try {
      context = std::make_unique<Context>(ContextOptions{"", validation});
    } catch (const DeviceError& e) {
      std::fprintf(stderr, "error: no Vulkan device (%s); --cpu-only runs the CPU checks alone\n", e.what());
      return 3;
    }
  }

  const Check all[] = {kBackends, kCutoff, kMetamorphic, kGround};
  std::map<Check, std::vector<std::string>> failedBy;
  std::map<Check, int> ran;
  std::map<std::string, int> kinds;
  std::vector<std::string> written;
  int scenesRun = 0, scenesFailed = 0;
  auto start = std::chrono::steady_clock::now();
  for (const Job& job : jobs) {
    auto t0 = std::chrono::steady_clock::now();
    CheckOptions options;
    options.checks = checks;
    options.stepBudget = job.budget;
    options.context = context.get();
    Outcome outcome = runChecks(job.text, job.name, options);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++scenesRun;
    if (job.generated) ++kinds[sceneKind(job.seed)];
    std::string failedChecks;
    for (Check c : all) {
      if (!(checks & c)) continue;
      ++ran[c];
      if (!outcome.passed(c)) {
        failedBy[c].push_back(job.generated ? std::to_string(job.seed) : job.name);
        failedChecks += checkLetter(c);
      }
    }
    if (verbose || !failedChecks.empty())
      std::printf("%s%s: %s (%.1f s)\n", job.name.c_str(),
                  job.generated ? (" (" + sceneKind(job.seed) + ")").c_str() : "",
                  failedChecks.empty() ? "ok" : ("FAILED " + failedChecks).c_str(), seconds);
    if (verbose)
      for (const std::string& note : outcome.notes) std::printf("  note: %s\n", note.c_str());
    if (failedChecks.empty()) continue;
    ++scenesFailed;
    fs::path dir = fs::path(outDir) / job.dirName;
    fs::create_directories(dir);
    std::string scenePath = (dir / "scene.test").string();
    std::string text = job.text;
    if (job.budget != 3 && text.find("# difftest-step-budget:") == std::string::npos)
      text = "# difftest-step-budget: " + std::to_string(job.budget) + "\n" + text;
    writeText(scenePath, text);
    std::printf("  scene:    %s\n", scenePath.c_str());
    for (const auto& [check, what] : outcome.problems) std::printf("  %s: %s\n", checkLetter(check), what.c_str());
    for (const Comparison& c : outcome.comparisons) {
      if (c.passed()) continue;
      std::printf("  %s %s: %lld pixels differ by more than %d/255 (allowed %lld), largest %d/255; worst: %s\n",
                  checkLetter(c.check), c.name.c_str(), c.over, c.stepTolerance, c.allowedOver, c.maxDiff,
                  c.worst.c_str());
      std::string base = (dir / c.name).string();
      try {
        writePngAtomic(c.actual, base + "-" + c.actualLabel + ".png");
        writePngAtomic(c.expected, base + "-" + c.expectedLabel + ".png");
        if (c.actual.width == c.expected.width && c.actual.height == c.expected.height)
          writePngAtomic(amplifiedDifference(c.actual, c.expected, 16), base + "-diff-x16.png");
      } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
      }
      std::printf("    %s-{%s,%s,diff-x16}.png\n", base.c_str(), c.actualLabel.c_str(), c.expectedLabel.c_str());
      if (!c.variantText.empty()) {
        writeText(base + ".test", c.variantText);
        std::printf("    %s.test\n", base.c_str());
      }
    }
    std::fflush(stdout);
  }
  double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("\nscenes run: %d in %.0f s", scenesRun, total);
  if (!kinds.empty()) {
    std::printf(" (");
    bool firstKind = true;
    for (const auto& [kind, n] : kinds) {
      std::printf("%s%s %d", firstKind ? "" : ", ", kind.c_str(), n);
      firstKind = false;
    }
    std::printf(")");
  }
  std::printf("; scenes with a disagreement: %d\n", scenesFailed);
  for (Check c : all) {
    if (!(checks & c)) continue;
    std::printf("check %s (%s): %zu of %d disagree", checkLetter(c), checkName(c), failedBy[c].size(), ran[c]);
    if (!failedBy[c].empty()) {
      std::printf(":");
      for (const std::string& s : failedBy[c]) std::printf(" %s", s.c_str());
    }
    std::printf("\n");
  }
  if (scenesFailed) std::printf("written under %s/\n", outDir.c_str());
  return scenesFailed ? 5 : 0;
}
