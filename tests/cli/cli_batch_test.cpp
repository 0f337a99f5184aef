// Several scenes in one run: a line per scene, a summary, the worst exit status, -o DIR/, and
// images equal to those of separate runs (the Vulkan context is shared between scenes).
#include <filesystem>

#include <gtest/gtest.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene =
    "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\nsphere 0 0 0 1\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// A bad scene between two good ones: its error and its line, the others rendered and
// written, the summary, and the exit status of the failure.
TEST(CliBatch, AFailedSceneDoesNotStopTheOthers) {
  std::string dir = freshDir("cli-batch/good-bad");
  writeFile(dir + "/good.test", kScene + "output " + dir + "/good.png\n");
  writeFile(dir + "/bad.test", "size 40 30\nsphere 0 0 0 1\noutput " + dir + "/bad.png\n");   // no camera
  writeFile(dir + "/later.test", kScene + "output " + dir + "/later.png\n");
  RunResult r = runVkrt("--backend cpu " + dir + "/good.test " + dir + "/bad.test " + dir + "/later.test");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: [1/3] ok      " + dir + "/good.test -> " + dir + "/good.png (40x30) in "))
      << r.output;
  EXPECT_TRUE(contains(r.output, dir + "/bad.test:3: error: no 'camera' command in the scene\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: [2/3] exit 2  " + dir + "/bad.test: scene error, nothing written, in "))
      << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: [3/3] ok      " + dir + "/later.test -> ")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: 3 scenes in ")) << r.output;
  EXPECT_TRUE(contains(r.output, " s: 2 rendered, 1 failed; exit status 2\n")) << r.output;
  EXPECT_EQ(readImage(dir + "/good.png").width, 40);
  EXPECT_TRUE(fileExists(dir + "/later.png"));
  EXPECT_FALSE(fileExists(dir + "/bad.png"));
  // -q: the failure's lines only.
  RunResult q = runVkrt("-q --backend cpu " + dir + "/good.test " + dir + "/bad.test");
  EXPECT_EQ(q.exitCode, 2);
  EXPECT_FALSE(contains(q.output, "ok ")) << q.output;
  EXPECT_TRUE(contains(q.output, "[2/2] exit 2")) << q.output;
  EXPECT_TRUE(contains(q.output, "1 rendered, 1 failed; exit status 2")) << q.output;
}

// The highest status of the scenes: an unreadable file (4) over a scene error (2), whatever
// the order; all good is 0.
TEST(CliBatch, TheExitStatusIsTheHighestOfTheScenes) {
  std::string dir = freshDir("cli-batch/worst");
  writeFile(dir + "/good.test", kScene);
  writeFile(dir + "/bad.test", "size 40 30\nsphere 0 0 0 1\n");
  std::string missing = dir + "/missing.test";
  RunResult a = runVkrt("--backend cpu -o " + dir + "/ " + missing + " " + dir + "/bad.test");
  EXPECT_EQ(a.exitCode, 4) << a.output;
  EXPECT_TRUE(contains(a.output, "[1/2] exit 4  " + missing + ": I/O error")) << a.output;
  RunResult b = runVkrt("--backend cpu -o " + dir + "/ " + dir + "/bad.test " + missing + " " + dir + "/good.test");
  EXPECT_EQ(b.exitCode, 4) << b.output;
  EXPECT_TRUE(contains(b.output, "1 rendered, 2 failed; exit status 4")) << b.output;
  writeFile(dir + "/good2.test", kScene);
  RunResult all = runVkrt("--backend cpu -o " + dir + "/ " + dir + "/good.test " + dir + "/good2.test");
  EXPECT_EQ(all.exitCode, 0) << all.output;
  EXPECT_TRUE(contains(all.output, "2 rendered, 0 failed; exit status 0")) << all.output;
}

// -o DIR/: the file name of the scene's `output`, or the stem + .png without one; the
// scene's own folder does not matter. -o FILE with several scenes is a usage error.
TEST(CliBatch, OutputDirectoryNamesEachImage) {
  std::string dir = freshDir("cli-batch/out-dir");
  std::filesystem::create_directories(dir + "/scenes/sub");
  std::filesystem::create_directories(dir + "/out");
  writeFile(dir + "/scenes/named.test", kScene + "output elsewhere/named-image.ppm\n");
  writeFile(dir + "/scenes/sub/plain.test", kScene);
  RunResult r = runVkrt("--backend cpu -o " + dir + "/out/ " + dir + "/scenes/named.test " + dir +
                        "/scenes/sub/plain.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(readImage(dir + "/out/named-image.ppm").width, 40);   // written as its name says: PPM
  EXPECT_EQ(readFile(dir + "/out/named-image.ppm").rfind("P6\n", 0), 0u);
  EXPECT_EQ(readImage(dir + "/out/plain.png").height, 30);
  EXPECT_EQ(fileCount(dir + "/out"), 2u);
  EXPECT_TRUE(contains(r.output, "-> " + dir + "/out/plain.png (40x30)")) << r.output;
  // One scene and -o DIR/ works the same way.
  RunResult one = runVkrt("--backend cpu -o " + dir + "/out/ " + dir + "/scenes/sub/plain.test");
  EXPECT_EQ(one.exitCode, 0) << one.output;
  EXPECT_TRUE(contains(one.output, "vkrt: wrote " + dir + "/out/plain.png (40x30)")) << one.output;
  // A folder that does not exist: the command line's I/O error, for each scene.
  RunResult none = runVkrt("--backend cpu -o " + dir + "/none/ " + dir + "/scenes/sub/plain.test " + dir +
                           "/scenes/named.test");
  EXPECT_EQ(none.exitCode, 4) << none.output;
  EXPECT_TRUE(contains(none.output, "0 rendered, 2 failed")) << none.output;
  RunResult file = runVkrt("-o " + dir + "/out/x.png " + dir + "/scenes/named.test " + dir + "/scenes/sub/plain.test");
  EXPECT_EQ(file.exitCode, 1) << file.output;
  EXPECT_TRUE(contains(file.output, "vkrt: error: -o " + dir + "/out/x.png names one file, for 2 scenes")) << file.output;
  EXPECT_EQ(fileCount(dir + "/out"), 2u);
  for (const char* alone : {"--check x.png", "--compare"}) {
    RunResult c = runVkrt(std::string(alone) + " " + dir + "/scenes/named.test " + dir + "/scenes/sub/plain.test");
    EXPECT_EQ(c.exitCode, 1) << alone << "\n" << c.output;
  }
}

// Two scenes that would write one file: the second is refused (a usage error, 1) and the
// first image stays.
TEST(CliBatch, TwoScenesWithOneOutputNameDoNotOverwriteEachOther) {
  std::string dir = freshDir("cli-batch/collision");
  writeFile(dir + "/a.test", kScene + "diffuse 0 0.5 0\nsphere 0 0 0 1\noutput " + dir + "/same.png\n");
  writeFile(dir + "/b.test", kScene + "output " + dir + "/./same.png\n");   // the same file, spelt otherwise
  RunResult r = runVkrt("--backend cpu " + dir + "/a.test " + dir + "/b.test");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(contains(r.output, "refusing to write the output of " + dir + "/b.test '" + dir +
                                     "/./same.png': it is also the output of " + dir + "/a.test")) << r.output;
  EXPECT_GT(readImage(dir + "/same.png").pixel(20, 15)[1], 50);   // a's green sphere
}

// --dry-run: each scene parsed and its output checked as a render would, the same messages and
// exit status, nothing rendered or written, and no device opened (here: no Vulkan driver to
// find). What a render refuses it refuses: two scenes that would write one file, a scene
// with an error, an output folder that does not exist.
TEST(CliBatch, ADryRunChecksWhatARenderWouldAndWritesNothing) {
  std::string dir = freshDir("cli-batch/dry-run");
  fs::create_directories(dir + "/out");
  writeFile(dir + "/a.test", kScene + "output same.png\n");
  writeFile(dir + "/b.test", kScene + "output other/same.png\n");   // the same name in -o DIR/
  writeFile(dir + "/c.test", kScene);
  writeFile(dir + "/bad.test", kScene + "sphere 0 0\n");
  const std::string noDriver = "VK_DRIVER_FILES=" + dir + "/none.json VK_ICD_FILENAMES=" + dir + "/none.json";
  RunResult ok = runVkrt("--dry-run -o " + dir + "/out/ " + dir + "/a.test " + dir + "/c.test", noDriver);
  EXPECT_EQ(ok.exitCode, 0) << ok.output;
  EXPECT_TRUE(contains(ok.output, dir + "/a.test -> " + dir + "/out/same.png (40x30), not rendered (--dry-run)"))
      << ok.output;
  EXPECT_TRUE(contains(ok.output, dir + "/c.test -> " + dir + "/out/c.png (40x30)")) << ok.output;
  EXPECT_TRUE(contains(ok.output, "2 scenes in")) << ok.output;
  EXPECT_TRUE(contains(ok.output, "2 checked (--dry-run: nothing rendered), 0 failed")) << ok.output;
  RunResult one = runVkrt("--dry-run --size 80x60 " + dir + "/c.test -o " + dir + "/out/c.png", noDriver);
  EXPECT_EQ(one.exitCode, 0) << one.output;
  EXPECT_TRUE(contains(one.output, dir + "/c.test -> " + dir + "/out/c.png (80x60), not rendered (--dry-run)"))
      << one.output;
  RunResult clash = runVkrt("--dry-run -o " + dir + "/out/ " + dir + "/a.test " + dir + "/b.test " + dir +
                            "/bad.test", noDriver);
  EXPECT_EQ(clash.exitCode, 2) << clash.output;   // the worst: the scene error
  EXPECT_TRUE(contains(clash.output, "refusing to write the output of " + dir + "/b.test")) << clash.output;
  EXPECT_TRUE(contains(clash.output, "it is also the output of " + dir + "/a.test")) << clash.output;
  EXPECT_TRUE(contains(clash.output, "bad.test:6: error: 'sphere' expects 4 arguments")) << clash.output;
  RunResult noFolder = runVkrt("--dry-run -o " + dir + "/missing/x.png " + dir + "/c.test", noDriver);
  EXPECT_EQ(noFolder.exitCode, 4) << noFolder.output;
  EXPECT_TRUE(fs::is_empty(dir + "/out"));   // nothing written, no temporary file
  EXPECT_EQ(runVkrt("--dry-run --watch " + dir + "/c.test").exitCode, 1);
  EXPECT_EQ(runVkrt("--dry-run --compare " + dir + "/c.test").exitCode, 1);
}

// --compare --time would compare renders of different sample counts: a usage error.
TEST(CliBatch, CompareRefusesATimeLimit) {
  std::string dir = freshDir("cli-batch/compare-time");
  writeFile(dir + "/c.test", kScene);
  RunResult r = runVkrt("--compare --time 1 " + dir + "/c.test");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_TRUE(contains(r.output, "under --time each would render as many as it can in the time: give --spp"))
      << r.output;
}

// Scenes rendered one after another on one Vulkan context give the images of separate runs.
TEST(CliBatch, SharingTheVulkanContextChangesNoPixel) {
  VKRT_REQUIRE_GPU(ctx);
  std::string dir = freshDir("cli-batch/vulkan");
  std::filesystem::create_directories(dir + "/batch");
  std::filesystem::create_directories(dir + "/single");
  const char* names[] = {"spheres", "shadows", "trinormal"};
  std::string all;
  for (const char* n : names) all += " " + sourcePath(std::string("scenes/") + n + ".test");
  RunResult batch = runVkrt("--backend vulkan -o " + dir + "/batch/" + all);
  ASSERT_EQ(batch.exitCode, 0) << batch.output;
  for (const char* n : names) {
    RunResult single = runVkrt("--backend vulkan -o " + dir + "/single/ " + sourcePath(std::string("scenes/") + n + ".test"));
    ASSERT_EQ(single.exitCode, 0) << single.output;
    std::string file = std::string("/") + n + ".png";
    EXPECT_TRUE(readImage(dir + "/batch" + file).rgb == readImage(dir + "/single" + file).rgb) << n;
  }
}
