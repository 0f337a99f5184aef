// The vkrt command line: options, exit statuses, messages, and what gets written where.
#include <gtest/gtest.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kScene =
    "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\nsphere 0 0 0 1\n";

}  // namespace

TEST(Cli, HelpAndVersion) {
  RunResult h = runVkrt("--help");
  EXPECT_EQ(h.exitCode, 0);
  EXPECT_NE(h.output.find("usage: vkrt [options] SCENE.test"), std::string::npos) << h.output;
  EXPECT_NE(h.output.find("--backend"), std::string::npos);
  RunResult v = runVkrt("--version");
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_EQ(v.output.rfind("vkrt ", 0), 0u) << v.output;
}

TEST(Cli, UsageErrorsExitWith1) {
  for (const char* args : {"", "--bogus x.test", "--threads 0 x.test", "--threads abc x.test", "--backend gl x.test",
                           "-o", "a.test b.test"}) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("vkrt: error: "), std::string::npos) << r.output;
  }
}

TEST(Cli, RendersToTheScenesOutputRelativeToTheCurrentDirectory) {
  std::string dir = freshDir("cli/scene-output");
  writeFile(dir + "/s.test", kScene + "output img.png\n");
  RunResult r = runVkrt("--backend cpu " + dir + "/s.test");   // run from the build folder
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: wrote img.png (40x30)"), std::string::npos) << r.output;
  Image img = readImage("img.png");
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 30);
  EXPECT_GT(img.pixel(20, 15)[0], 100);
  std::remove("img.png");
}

TEST(Cli, OutputOptionOverridesAndStatsArePrinted) {
  std::string dir = freshDir("cli/override");
  writeFile(dir + "/s.test", kScene + "output never.png\n");
  RunResult r = runVkrt("--backend cpu --stats --threads 1 -o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fileExists(dir + "/o.png"));
  EXPECT_FALSE(fileExists("never.png"));
  for (const char* key : {"parse", "build", "render", "write", "rays", "primary 1200", "1 threads"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
  RunResult eq = runVkrt("-q --output=" + dir + "/eq.png " + dir + "/s.test");
  EXPECT_EQ(eq.exitCode, 0) << eq.output;
  EXPECT_EQ(eq.output, "");   // --quiet
  EXPECT_TRUE(fileExists(dir + "/eq.png"));
}

TEST(Cli, UnwritableOutputOptionIsAnIoErrorBeforeRendering) {
  std::string dir = freshDir("cli/io");
  writeFile(dir + "/s.test", kScene);
  RunResult r = runVkrt("-o " + dir + "/missing/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote"), std::string::npos);
}

TEST(Cli, NonTerminalGetsAPlainFinalLineAndNoProgressBar) {
  std::string dir = freshDir("cli/plain");
  writeFile(dir + "/s.test", kScene);
  RunResult r = runVkrt("-o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "progress bar drawn into a pipe";
  EXPECT_EQ(r.output.rfind("vkrt: wrote ", 0), 0u) << r.output;
}
