// `vkrt grade` end to end: a class of folders against references, into a report folder whose
// summaries say what each comparison found; images side by side as one submission; scene
// files rendered and graded; and the report folder never taking what the user had.
#include <filesystem>

#include <gtest/gtest.h>

#include "image/png.h"
#include "image/ppm.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.pixel(x, y)[0] = r, im.pixel(x, y)[1] = g, im.pixel(x, y)[2] = b;
  return im;
}

// `im` with `n` pixels of row 0 raised by `steps` in green.
Image withOff(Image im, int n, int steps) {
  for (int x = 0; x < n; ++x) im.pixel(x, 0)[1] = static_cast<std::uint8_t>(im.pixel(x, 0)[1] + steps);
  return im;
}

// Entries of `dir` whose name starts with ".vkrt-grade": temporary folders left behind.
std::size_t leftovers(const std::string& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".vkrt-grade", 0) == 0) ++n;
  return n;
}

// The references a, b, c (PPM) and ref_d, and three students.
struct Class {
  std::string dir, refs, subs;
  Image a = gradient(64, 48), b = solid(32, 24, 200, 30, 30), c = gradient(40, 30), d = solid(16, 16, 0, 90, 200);
};

Class makeClass(const std::string& name) {
  Class k;
  k.dir = freshDir(name);
  k.refs = k.dir + "/refs", k.subs = k.dir + "/subs";
  for (const std::string& f : {k.refs, k.subs + "/alice/hw", k.subs + "/bob", k.subs + "/carol"}) fs::create_directories(f);
  writePngAtomic(k.a, k.refs + "/a.png");
  writePngAtomic(k.b, k.refs + "/b.png");
  writePpmAtomic(k.c, k.refs + "/c.ppm");
  writePngAtomic(k.d, k.refs + "/ref_d.png");
  // alice: all as the references (b one folder down, c as PNG where the reference is PPM).
  writePngAtomic(k.a, k.subs + "/alice/a.png");
  writePngAtomic(k.b, k.subs + "/alice/hw/b.png");
  writePngAtomic(k.c, k.subs + "/alice/C.png");
  writePngAtomic(k.d, k.subs + "/alice/d.png");
  // bob: a 5 pixels off by 10 (over the 3 allowed), b missing, c another size, d 2 pixels
  // off (allowed), and an image of no scene.
  writePngAtomic(withOff(k.a, 5, 10), k.subs + "/bob/a.png");
  writePngAtomic(gradient(41, 30), k.subs + "/bob/c.png");
  writePngAtomic(withOff(k.d, 2, 10), k.subs + "/bob/d.png");
  writePngAtomic(k.d, k.subs + "/bob/e.png");
  // carol: a that is not an image.
  writeFile(k.subs + "/carol/a.png", "not an image\n");
  return k;
}

}  // namespace

TEST(GradeCli, AClassOfFoldersGradedIntoAReport) {
  Class k = makeClass("grade/class");
  const std::string report = k.dir + "/report";
  const std::string before = readFile(k.subs + "/bob/a.png");
  writeFile(k.dir + "/t.txt", "b --max-diff 0\n");
  RunResult r = runVkrt("grade " + k.refs + " " + k.subs + " -o " + report + " --max-pixels-over 2:3 --thresholds " +
                        k.dir + "/t.txt");
  EXPECT_EQ(r.exitCode, 5) << r.output;   // a failure and a missing image (5) over an unreadable one (4)
  EXPECT_TRUE(contains(r.output, "vkrt: alice                4/4 pass\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: bob                  1/4 pass; fail: a, c; missing: b\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: carol: a: cannot read image '" + k.subs + "/carol/a.png'")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: carol                0/4 pass; missing: b, c, d; unreadable: a\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: note: bob: " + k.subs + "/bob/e.png: no reference image is named for this scene"))
      << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: graded 3 submissions x 4 scenes in ")) << r.output;
  EXPECT_TRUE(contains(r.output, ": 5 pass, 2 fail, 4 missing, 1 unreadable; report: " + report + "/index.html; exit status 5\n"))
      << r.output;

  // The figures for scripts, a row per comparison.
  const std::string csv = readFile(report + "/summary.csv");
  EXPECT_TRUE(contains(csv, "submission,scene,status,key_figure,max_channel_diff,")) << csv;
  EXPECT_TRUE(contains(csv, "alice,b,pass,0,0,0,inf,0,0,0,0,0," + k.subs + "/alice/hw/b.png,\n")) << csv;
  EXPECT_TRUE(contains(csv, "bob,a,fail,5,10,")) << csv;
  EXPECT_TRUE(contains(csv, "bob,b,missing,,,,,,,,,,,\n")) << csv;
  EXPECT_TRUE(contains(csv, "bob,c,fail,,,,,,,,,," + k.subs + "/bob/c.png,\"the image is 41x30, the reference 40x30\"\n"))
      << csv;
  EXPECT_TRUE(contains(csv, "bob,d,pass,2,10,")) << csv;
  EXPECT_TRUE(contains(csv, "carol,a,unreadable,")) << csv;
  const std::string json = readFile(report + "/summary.json");
  EXPECT_TRUE(contains(json, "\"counts\": {\"pass\": 5, \"fail\": 2, \"missing\": 4, \"unreadable\": 1}")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"b\", \"reference\": \"" + k.refs + "/b.png\", \"width\": 32, \"height\": 24, "
                             "\"thresholds\": \"--max-diff 0\", \"key_figure\": \"largest difference (/255)\"}"))
      << json;
  EXPECT_TRUE(contains(json, "\"thresholds\": \"--max-pixels-over 2:3\"")) << json;

  // The pages: the overview names everyone; bob's a is boxed where it fails; the images are
  // the submitted ones; a missing image has no page.
  const std::string index = readFile(report + "/index.html");
  for (const char* name : {">alice<", ">bob<", ">carol<", ">ref_d<"}) EXPECT_EQ(contains(index, name), name != std::string(">ref_d<")) << name;
  EXPECT_TRUE(contains(index, ">d<br>")) << "the scene of ref_d.png is d";
  const std::string bobA = readFile(report + "/pages/s0002-c001.html");
  EXPECT_TRUE(contains(bobA, "5 pixels (0.1628%) differ by more than 2/255; allowed: 3 (--max-pixels-over 2:3)")) << bobA;
  EXPECT_TRUE(contains(bobA, "<span class=\"region\" style=\"left:0.000%;top:0.000%;width:25.000%;height:33.333%\"")) << bobA;
  EXPECT_EQ(readImage(report + "/images/s0002/c001.png").rgb, withOff(k.a, 5, 10).rgb);
  EXPECT_EQ(readImage(report + "/images/ref/c003.png").rgb, k.c.rgb);
  EXPECT_EQ(readImage(report + "/images/s0002/c001-thumb.png").width, 64);   // fits 96x72 already
  EXPECT_TRUE(fileExists(report + "/images/s0002/c001-diff.png"));
  EXPECT_FALSE(fileExists(report + "/pages/s0002-c002.html"));
  EXPECT_TRUE(fileExists(report + "/pages/s0003-c001.html"));
  // What it read is as it was; nothing temporary is left.
  EXPECT_EQ(readFile(k.subs + "/bob/a.png"), before);
  EXPECT_EQ(leftovers(k.dir), 0u);
}

// A folder of images is one submission, named for the folder; all passing: exit 0, and -q
// prints nothing.
TEST(GradeCli, ImagesSideBySideAreOneSubmission) {
  Class k = makeClass("grade/side-by-side");
  RunResult r = runVkrt("grade -q " + k.refs + " " + k.subs + "/alice/hw -o " + k.dir + "/report");
  EXPECT_EQ(r.exitCode, 5) << r.output;   // only b there: a, c and d missing
  EXPECT_TRUE(contains(r.output, "vkrt: graded 1 submission x 4 scenes in ")) << r.output;
  EXPECT_TRUE(contains(readFile(k.dir + "/report/summary.csv"), "hw,b,pass,")) << readFile(k.dir + "/report/summary.csv");
  fs::create_directories(k.dir + "/flat");
  for (const char* f : {"a.png", "C.png", "d.png"}) fs::copy_file(k.subs + "/alice/" + f, k.dir + "/flat/" + f);
  fs::copy_file(k.subs + "/alice/hw/b.png", k.dir + "/flat/b.png");
  RunResult all = runVkrt("grade -q " + k.refs + " " + k.dir + "/flat -o " + k.dir + "/report");
  EXPECT_EQ(all.exitCode, 0) << all.output;
  EXPECT_EQ(all.output, "");
  EXPECT_TRUE(contains(readFile(k.dir + "/report/summary.json"), "\"name\": \"flat\"")) << "the earlier report replaced";
}

// Scene files are rendered in the run (nothing written beside them) and graded against the
// references of their names; a scene that cannot be rendered gives its own status.
TEST(GradeCli, SceneFilesAreRenderedAndGraded) {
  std::string dir = freshDir("grade/render");
  fs::create_directories(dir + "/refs");
  const std::string scene = "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 2 2 4 1 1 1\ndiffuse 0.6 0.3 0.1\nsphere 0 0 0 1\n";
  writeFile(dir + "/ball.test", scene + "output " + dir + "/ball-out.png\n");
  writeFile(dir + "/flat.test", "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 0.2 0.4 0.6\nsphere 0 0 0 1\n");
  writeFile(dir + "/broken.test", "size 40 30\nsphere 0 0 0 1\n");   // no camera
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/refs/ball.png " + dir + "/ball.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/refs/flat.png " + dir + "/flat.test").exitCode, 0);
  writePngAtomic(solid(40, 30, 1, 2, 3), dir + "/refs/broken.png");
  RunResult ok = runVkrt("grade --backend cpu " + dir + "/refs " + dir + "/ball.test " + dir + "/flat.test -o " + dir + "/report");
  EXPECT_EQ(ok.exitCode, 5) << ok.output;   // broken.test not given: missing
  EXPECT_TRUE(contains(ok.output, "vkrt: vkrt                 2/3 pass; missing: broken\n")) << ok.output;
  EXPECT_FALSE(fileExists(dir + "/ball-out.png"));
  // The Vulkan backend's renders against the CPU reference's, within a step; with the
  // broken scene: its error, its status (2) over the others' (0).
  RunResult gpu = runVkrt("grade --max-diff 1 " + dir + "/refs " + dir + "/ball.test " + dir + "/flat.test " + dir +
                          "/broken.test -o " + dir + "/report");
  EXPECT_EQ(gpu.exitCode, 4) << gpu.output;
  EXPECT_TRUE(contains(gpu.output, dir + "/broken.test:2: error: no 'camera' command in the scene")) << gpu.output;
  EXPECT_TRUE(contains(gpu.output, "vkrt: vkrt                 2/3 pass; unreadable: broken\n")) << gpu.output;
  EXPECT_TRUE(contains(readFile(dir + "/report/summary.csv"), "vkrt,broken,unreadable,")) << readFile(dir + "/report/summary.csv");
}

TEST(GradeCli, TheReportFolderNeverTakesWhatTheUserHad) {
  Class k = makeClass("grade/refused");
  const std::string grade = "grade -q " + k.refs + " " + k.subs + " -o ";
  auto refused = [&](const std::string& output, const std::string& message) {
    RunResult r = runVkrt(grade + output);
    EXPECT_EQ(r.exitCode, 1) << output << ": " << r.output;
    EXPECT_TRUE(contains(r.output, message)) << r.output;
  };
  refused(k.subs, "the report folder is '" + k.subs + "', which this run reads");
  refused(k.subs + "/alice", "the report folder lies in '" + k.subs + "'");
  refused(k.dir, "the report folder holds '" + k.subs + "'");
  fs::create_directories(k.dir + "/notes");
  writeFile(k.dir + "/notes/todo.txt", "mine\n");
  refused(k.dir + "/notes", "is a folder that holds other files than a vkrt report");
  EXPECT_EQ(readFile(k.dir + "/notes/todo.txt"), "mine\n");
  writeFile(k.dir + "/file", "mine\n");
  refused(k.dir + "/file", "is a file, not a folder for the report");
  // An earlier report is replaced whole; one with a file someone added is not.
  ASSERT_EQ(runVkrt(grade + k.dir + "/report").exitCode, 5);
  ASSERT_EQ(runVkrt(grade + k.dir + "/report").exitCode, 5);
  writeFile(k.dir + "/report/my-notes.txt", "mine\n");
  refused(k.dir + "/report", "holds other files than a vkrt report");
  EXPECT_EQ(readFile(k.dir + "/report/my-notes.txt"), "mine\n");
  // An empty folder takes it (a link to one is written through and stays a link).
  fs::create_directories(k.dir + "/empty");
  fs::create_directory_symlink(k.dir + "/empty", k.dir + "/link");
  EXPECT_EQ(runVkrt(grade + k.dir + "/link").exitCode, 5);
  EXPECT_TRUE(fs::is_symlink(k.dir + "/link"));
  EXPECT_TRUE(fileExists(k.dir + "/empty/index.html"));
  EXPECT_EQ(leftovers(k.dir), 0u);
}

TEST(GradeCli, UsageErrorsSayWhatIsMissing) {
  Class k = makeClass("grade/usage");
  auto usage = [&](const std::string& args, const std::string& message) {
    RunResult r = runVkrt("grade " + args);
    EXPECT_EQ(r.exitCode, 1) << args << ": " << r.output;
    EXPECT_TRUE(contains(r.output, message)) << args << ": " << r.output;
  };
  usage(k.refs + " -o " + k.dir + "/r", "grade needs the references' folder and at least one folder of submissions");
  usage(k.refs + " " + k.subs, "grade needs the report's folder: vkrt grade REFS/ SUBMISSIONS/ -o REPORT/");
  usage(k.refs + " " + k.subs + " -o " + k.dir + "/r --max-dif 2", "did you mean '--max-diff'?");
  usage(k.refs + " " + k.subs + "/bob/a.png -o " + k.dir + "/r", "is a PNG image; give the folder that holds");
  usage(k.refs + " " + k.subs + " -o " + k.dir + "/r --max-bias x", "--max-bias expects a number of 0 or more");
  RunResult none = runVkrt("grade " + k.subs + " " + k.subs + "/alice -o " + k.dir + "/r");
  EXPECT_EQ(none.exitCode, 1) << none.output;
  EXPECT_TRUE(contains(none.output, "no reference image in '" + k.subs + "'")) << none.output;
  RunResult absent = runVkrt("grade " + k.dir + "/nothing " + k.subs + " -o " + k.dir + "/r");
  EXPECT_EQ(absent.exitCode, 4) << absent.output;
  EXPECT_TRUE(contains(absent.output, "the references '" + k.dir + "/nothing' are not a folder")) << absent.output;
  EXPECT_FALSE(fileExists(k.dir + "/r"));
  EXPECT_TRUE(contains(runVkrt("grad a b").output, "did you mean 'grade'?"));
}
