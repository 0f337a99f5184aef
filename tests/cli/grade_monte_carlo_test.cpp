// `vkrt grade`'s default verdict for path-traced scenes (--max-bias-z 6, compare/bias_test.h)
// on real renders: the reference from the CPU backend (double precision, written apart from
// the shader) at 1024 samples; the submissions from the Vulkan path tracer, correct at 4, 16
// and 64 samples, and with the bugs students make: a path cut short (maxdepth 2 for 5) at 16
// and 64 samples, a light 10% too dim at 16 and 5% too dim at 64 (at 16 samples, 5% is within
// the noise of this 48x48 image's 16x16 squares). The correct ones must pass and the biased ones fail,
// whether the scene's file lies beside the reference or is rendered in the run; without a
// scene file the default stays "any difference fails".
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace vkrt::test;

namespace fs = std::filesystem;

namespace {

// The scene at `size` x `size`, with its quad light's radiance times `light` and the depth
// `maxdepth` (its own when 0).
std::string variant(const std::string& text, int size, double light, int maxdepth) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string cmd;
    words >> cmd;
    if (cmd == "size") line = "size " + std::to_string(size) + " " + std::to_string(size);
    if (cmd == "maxdepth" && maxdepth > 0) line = "maxdepth " + std::to_string(maxdepth);
    if (cmd == "quadLight") {
      double v[12];
      for (double& x : v) words >> x;
      std::ostringstream q;
      q << "quadLight";
      for (int i = 0; i < 12; ++i) q << " " << (i >= 9 ? v[i] * light : v[i]);
      line = q.str();
    }
    out += line + "\n";
  }
  return out;
}

// Each submission's status in REPORT/summary.json.
std::map<std::string, std::string> statuses(const std::string& report) {
  const std::string json = readFile(report + "/summary.json");
  std::map<std::string, std::string> s;
  const std::regex entry("\\{\"name\": \"([^\"]+)\", \"folder\"[^\\]]*\\],\\s*\"results\": \\[\\s*\\{[^}]*\"status\": \"([a-z]+)\"");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), entry); it != std::sregex_iterator(); ++it)
    s[(*it)[1]] = (*it)[2];
  return s;
}

}  // namespace

TEST(GradeMonteCarlo, CorrectRendersPassTheirNoiseAndBiasedOnesFail) {
  auto data = cse168Dir();
  if (!data) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  const std::string scene = readFile(*data + "/scenes/hw3/cornellNEE.test");
  ASSERT_NE(scene.find("maxdepth 5"), std::string::npos);
  const std::string dir = freshDir("grade/monte-carlo");
  const std::string refs = dir + "/refs", subs = dir + "/subs", bare = dir + "/bare-refs";
  fs::create_directories(refs), fs::create_directories(subs), fs::create_directories(bare);
  const int size = 48;
  writeFile(refs + "/cornellNEE.test", variant(scene, size, 1.0, 0));
  RunResult r = runVkrt("'" + refs + "/cornellNEE.test' --backend cpu --spp 1024 --seed 99 -q -o '" + refs +
                        "/cornellNEE.png'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  fs::copy_file(refs + "/cornellNEE.png", bare + "/cornellNEE.png");

  struct Variant {
    std::string name;
    double light;
    int maxdepth, spp;
    bool correct;
  };
  const Variant variants[] = {{"correct-4", 1.0, 0, 4, true},    {"correct-16", 1.0, 0, 16, true},
                              {"correct-64", 1.0, 0, 64, true},  {"maxdepth2-16", 1.0, 2, 16, false},
                              {"maxdepth2-64", 1.0, 2, 64, false}, {"dim10-16", 0.90, 0, 16, false},
                              {"dim5-64", 0.95, 0, 64, false}};
  for (const Variant& v : variants) {
    const std::string folder = subs + "/" + v.name;
    fs::create_directories(folder);
    writeFile(dir + "/" + v.name + ".test", variant(scene, size, v.light, v.maxdepth));
    r = runVkrt("'" + dir + "/" + v.name + ".test' --spp " + std::to_string(v.spp) + " --seed 7 -q -o '" + folder +
                "/cornellNEE.png'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }

  // The scene file beside the reference: the default judges by the noise.
  r = runVkrt("grade '" + refs + "' '" + subs + "' -q -o '" + dir + "/report'");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  const std::string json = readFile(dir + "/report/summary.json");
  EXPECT_NE(json.find("\"thresholds\": \"--max-bias-z 6 (the default of a path-traced scene)\""), std::string::npos)
      << json;
  std::map<std::string, std::string> got = statuses(dir + "/report");
  for (const Variant& v : variants) EXPECT_EQ(got[v.name], v.correct ? "pass" : "fail") << v.name << "\n" << json;

  // The scene rendered in the run, no file beside the reference: the same default.
  r = runVkrt("grade '" + bare + "' '" + refs + "/cornellNEE.test' --spp 16 --seed 3 -q -o '" + dir + "/rendered'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(statuses(dir + "/rendered")["vkrt"], "pass") << readFile(dir + "/rendered/summary.json");

  // No scene file at all: nothing says the scene is path-traced, and any difference fails.
  r = runVkrt("grade '" + bare + "' '" + subs + "' -q -o '" + dir + "/bare'");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  got = statuses(dir + "/bare");
  EXPECT_EQ(got["correct-64"], "fail");
  EXPECT_NE(readFile(dir + "/bare/summary.json").find("\"thresholds\": \"any difference fails\""), std::string::npos);

  // A threshold given takes the default's place: the teacher's rule is the rule.
  r = runVkrt("grade '" + refs + "' '" + subs + "' --max-bias 100 -q -o '" + dir + "/given'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
}
