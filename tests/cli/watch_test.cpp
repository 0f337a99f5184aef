// vkrt --watch (host/cli/watch.h): each change of the scene file, in place or by renaming a
// new file over it as editors save, renders again, and the image is what a fresh process
// renders of the file as it then is; a scene with an error leaves the last image and waits;
// a path-traced scene refines into the mean of the batches its record names (checked against
// vkrt merge of the same batches rendered apart); Ctrl-C ends it with status 130 and no
// temporary file.
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "image/image_file.h"
#include "image/samples.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

// Waits (at most `seconds`) until the log holds `text`; false when it never does.
bool logShows(const std::string& logPath, const std::string& text, double seconds = 60) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fileExists(logPath) && readFile(logPath).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Saves as many editors do: a new file renamed over the old one.
void saveByRename(const std::string& path, const std::string& text) {
  writeFile(path + ".new", text);
  ASSERT_EQ(std::rename((path + ".new").c_str(), path.c_str()), 0);
}

std::string whittedScene(const char* diffuse) {
  return std::string("size 32 24\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 2 2 2 1 1 1\nambient 0.1 0.1 0.1\ndiffuse ") +
         diffuse + "\nsphere 0 0 0 1\n";
}

void watchFollowsEdits(const std::string& backend) {
  const std::string dir = freshDir("watch/edits-" + backend);
  const std::string scene = dir + "/s.test", out = dir + "/out.png", log = dir + "/log";
  writeFile(scene, whittedScene("0.8 0.2 0.2"));
  Spawned watching = spawnVkrt({"--watch", "--backend", backend, "-o", out, scene}, log);
  auto fresh = [&](const std::string& name) {
    RunResult r = runVkrt("--backend " + backend + " -q -o " + dir + "/" + name + " " + scene);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readImage(dir + "/" + name).rgb;
  };
  ASSERT_TRUE(logShows(log, "vkrt: watch: [1] wrote " + out)) << readFile(log);
  EXPECT_EQ(readImage(out).rgb, fresh("fresh1.png"));

  saveByRename(scene, whittedScene("0.2 0.8 0.2"));
  ASSERT_TRUE(logShows(log, "vkrt: watch: [2] wrote " + out)) << readFile(log);
  const auto second = fresh("fresh2.png");
  EXPECT_EQ(readImage(out).rgb, second);

  writeFile(scene, whittedScene("0.2 0.8 0.2") + "sphere 0 0 0\n");   // in place, with an error
  ASSERT_TRUE(logShows(log, "nothing written; waiting for the next change of " + scene)) << readFile(log);
  EXPECT_NE(readFile(log).find("s.test:7: error: 'sphere' expects 4 arguments"), std::string::npos) << readFile(log);
  EXPECT_EQ(readImage(out).rgb, second);   // the last good image stays

  writeFile(scene, whittedScene("0.2 0.2 0.8") + "sphre 1 1 1 0.2\n");   // fixed; a typo warned of
  ASSERT_TRUE(logShows(log, "vkrt: watch: [4] wrote " + out)) << readFile(log);
  EXPECT_NE(readFile(log).find("1 warning"), std::string::npos) << readFile(log);
  EXPECT_EQ(readImage(out).rgb, fresh("fresh4.png"));

  ::kill(watching.pid, SIGINT);
  Finished done = waitVkrtWithin(watching, 30);
  EXPECT_EQ(done.exitCode, 130) << done.output;
  EXPECT_NE(done.output.find("vkrt: watch: stopped"), std::string::npos) << done.output;
  // The scene, the log, the image and the three fresh renders: no temporary file.
  EXPECT_EQ(fileCount(dir), 6u);
}

// Waits until the log holds `text` `count` times.
bool logShowsTimes(const std::string& logPath, const std::string& text, int count, double seconds = 60) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fileExists(logPath)) {
      const std::string log = readFile(logPath);
      int n = 0;
      for (std::size_t at = log.find(text); at != std::string::npos; at = log.find(text, at + 1)) ++n;
      if (n >= count) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

}  // namespace

// A scene given as a symbolic link renders again when it is written through the link, when
// its target is written or replaced, and a scene whose folder is removed and made again, or
// which is deleted and written again, is followed too: each said as it happens, none missed.
TEST(Watch, FollowsALinkAFolderMadeAgainAndADeletion) {
  const std::string dir = freshDir("watch/links");
  fs::create_directories(dir + "/real");
  const std::string target = dir + "/real/target.test", link = dir + "/link.test", log = dir + "/log";
  writeFile(target, whittedScene("0.8 0.2 0.2"));
  fs::create_symlink("real/target.test", link);
  Spawned watching = spawnVkrt({"--watch", "--backend", "cpu", "-o", dir + "/l.png", link}, log);
  ASSERT_TRUE(logShows(log, "[1] wrote")) << readFile(log);
  writeFile(link, whittedScene("0.2 0.8 0.2"));   // through the link
  ASSERT_TRUE(logShows(log, "[2] wrote")) << readFile(log);
  writeFile(target, whittedScene("0.2 0.2 0.8"));   // the target itself
  ASSERT_TRUE(logShows(log, "[3] wrote")) << readFile(log);
  saveByRename(target, whittedScene("0.5 0.5 0.5"));   // a new target renamed into place
  ASSERT_TRUE(logShows(log, "[4] wrote")) << readFile(log);
  EXPECT_EQ(readImage(dir + "/l.png").rgb, [&] {
    EXPECT_EQ(runVkrt("--backend cpu -q -o " + dir + "/fresh.png " + link).exitCode, 0);
    return readImage(dir + "/fresh.png").rgb;
  }());
  ::kill(watching.pid, SIGINT);
  EXPECT_EQ(waitVkrtWithin(watching, 30).exitCode, 130);

  // The scene's folder removed and made again (a checkout can do this), then the scene deleted.
  const std::string sub = dir + "/sub", scene = sub + "/x.test", log2 = dir + "/log2";
  fs::create_directories(sub);
  writeFile(scene, whittedScene("0.8 0.2 0.2"));
  Spawned again = spawnVkrt({"--watch", "--backend", "cpu", "-o", dir + "/x.png", scene}, log2);
  ASSERT_TRUE(logShows(log2, "[1] wrote")) << readFile(log2);
  fs::remove_all(sub);
  fs::create_directories(sub);
  writeFile(scene, whittedScene("0.2 0.8 0.2"));
  ASSERT_TRUE(logShows(log2, "[2] wrote")) << readFile(log2);
  writeFile(scene, whittedScene("0.2 0.2 0.8"));   // and edits after it are still seen
  ASSERT_TRUE(logShows(log2, "[3] wrote")) << readFile(log2);
  fs::remove(scene);
  ASSERT_TRUE(logShowsTimes(log2, "waiting for the next change of " + scene, 1)) << readFile(log2);
  EXPECT_NE(readFile(log2).find("cannot open scene file"), std::string::npos) << readFile(log2);
  writeFile(scene, whittedScene("0.5 0.5 0.5"));
  ASSERT_TRUE(logShows(log2, "[5] wrote")) << readFile(log2);
  ::kill(again.pid, SIGINT);
  EXPECT_EQ(waitVkrtWithin(again, 30).exitCode, 130);
  // One render per change: no change seen twice.
  EXPECT_EQ(readFile(log2).find("[6]"), std::string::npos) << readFile(log2);
}

// The folder holding the scene swapped in by rename (a deployment, a checkout): the watch on
// the folder follows the old one away, so no event names the scene; only the file's identity
// (another device and inode) tells vkrt, which renders again, and follows later edits there.
TEST(Watch, AFolderSwappedInByRenameIsSeenByTheFilesIdentity) {
  const std::string dir = freshDir("watch/folder-swap");
  fs::create_directories(dir + "/live");
  const std::string scene = dir + "/live/s.test", out = dir + "/out.png", log = dir + "/log";
  writeFile(scene, whittedScene("0.8 0.2 0.2"));
  Spawned watching = spawnVkrt({"--watch", "--backend", "cpu", "-o", out, scene}, log);
  ASSERT_TRUE(logShows(log, "[1] wrote")) << readFile(log);
  fs::create_directories(dir + "/next");
  writeFile(dir + "/next/s.test", whittedScene("0.2 0.8 0.2"));
  fs::rename(dir + "/live", dir + "/old");
  fs::rename(dir + "/next", dir + "/live");
  ASSERT_TRUE(logShows(log, "[2] wrote")) << readFile(log);
  auto fresh = [&](const std::string& name) {
    EXPECT_EQ(runVkrt("--backend cpu -q -o " + dir + "/" + name + " " + scene).exitCode, 0);
    return readImage(dir + "/" + name).rgb;
  };
  EXPECT_EQ(readImage(out).rgb, fresh("fresh2.png"));
  writeFile(scene, whittedScene("0.2 0.2 0.8"));   // an edit in the new folder: its events are watched now
  ASSERT_TRUE(logShows(log, "[3] wrote")) << readFile(log);
  EXPECT_EQ(readImage(out).rgb, fresh("fresh3.png"));
  writeFile(dir + "/old/s.test", whittedScene("0.5 0.5 0.5"));   // the old folder is no longer the scene's
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  ::kill(watching.pid, SIGINT);
  EXPECT_EQ(waitVkrtWithin(watching, 30).exitCode, 130);
  EXPECT_EQ(readFile(log).find("[4]"), std::string::npos) << readFile(log);
}

// An output named on the command line in a folder that does not exist: no edit of the scene
// can fix it, so --watch exits 4 at once instead of waiting.
TEST(Watch, AnOutputThatCannotBeWrittenEndsIt) {
  const std::string dir = freshDir("watch/no-output-folder");
  writeFile(dir + "/s.test", whittedScene("0.8 0.2 0.2"));
  for (const std::string& output : {dir + "/missing/x.png", dir + "/missing/"}) {
    // (timeout: a watch that waits would never end the test.)
    RunResult r = runCommand("timeout 60 '" + vkrtBinary() + "' --watch --backend cpu -o " + output + " " + dir +
                             "/s.test");
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_NE(r.output.find("output directory '" + dir + "/missing' does not exist"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("waiting"), std::string::npos) << r.output;
  }
}

TEST(Watch, RendersAgainAtEachChangeOnTheCpu) { watchFollowsEdits("cpu"); }

TEST(Watch, RendersAgainAtEachChangeOnVulkan) {
  if (!gpuContextOrSkip()) return;
  watchFollowsEdits("vulkan");
}

// The refined image is the mean of the batches its vkrt-samples record names, bit for bit.
TEST(Watch, APathTracedSceneRefinesIntoTheMeanOfItsBatches) {
  const std::string dir = freshDir("watch/refine");
  const std::string scene = dir + "/s.test", out = dir + "/out.pfm", log = dir + "/log";
  writeFile(scene,
            "size 12 9\ncamera 0 -3 1 0 0 0.5 0 0 1 45\nintegrator pathtracer\nspp 2\nnexteventestimation on\n"
            "quadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\nvertex -3 -3 0\nvertex 3 -3 0\n"
            "vertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\nsphere 0 0 0.5 0.5\n");
  Spawned watching = spawnVkrt({"--watch", "--backend", "cpu", "--seed", "40", "-o", out, scene}, log);
  ASSERT_TRUE(logShows(log, "(3 of 64 batches)")) << readFile(log);
  ::kill(watching.pid, SIGTERM);
  Finished done = waitVkrtWithin(watching, 30);
  EXPECT_EQ(done.exitCode, 143) << done.output;
  const RadianceImage refined = readFloatImage(out);
  std::optional<SampleRecord> record;
  for (const auto& [keyword, text] : refined.text)
    if (keyword == kSamplesKeyword) record = parseSampleRecord(text);
  ASSERT_TRUE(record);
  ASSERT_GE(record->ranges.size(), 3u);
  std::string batches;
  for (std::size_t k = 0; k < record->ranges.size(); ++k) {
    EXPECT_EQ(record->ranges[k].seed, 40u + k);
    EXPECT_EQ(record->ranges[k].count, 2u);
    const std::string batch = dir + "/batch-" + std::to_string(k) + ".pfm";
    RunResult r = runVkrt("--backend cpu -q --seed " + std::to_string(40 + k) + " -o " + batch + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    batches += " " + batch;
  }
  RunResult merged = runVkrt("merge -q -o " + dir + "/merged.pfm" + batches);
  ASSERT_EQ(merged.exitCode, 0) << merged.output;
  EXPECT_TRUE(sameBits(readFloatImage(dir + "/merged.pfm"), refined));
}

TEST(Watch, OptionsThatDoNotGoWithItAreUsageErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"--watch a.test b.test", "--watch takes one scene, got 2"},
      {"--watch --compare a.test", "--compare does not go with it"},
      {"--watch --check r.png a.test", "--check does not go with it"},
      {"--watch --time 3 a.test", "--time does not go with it"},
  };
  for (const auto& [args, message] : cases) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
}
