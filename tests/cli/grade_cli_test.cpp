// `vkrt grade` end to end: a class of folders against references, into a report folder whose
// summaries say what each comparison found; images side by side as one submission; scene
// files rendered and graded; and the report folder never taking what the user had.
#include <cmath>
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
  writePngAtomic(k.a, k.subs + "/bob/ref_a.png");   // a copy of the reference: not bob's image of a
  // carol: a that is not an image. dan: an empty folder; =eve: a file vkrt does not read.
  writeFile(k.subs + "/carol/a.png", "not an image\n");
  fs::create_directories(k.subs + "/dan");
  fs::create_directories(k.subs + "/=eve");
  writeFile(k.subs + "/=eve/a.bmp", "BM\n");
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
  EXPECT_TRUE(contains(r.output, "vkrt: note: bob: " + k.subs + "/bob/ref_a.png: no reference image is named for this scene"))
      << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: dan                  0/4 pass; missing: a, b, c, d\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: note: dan: no image in " + k.subs + "/dan\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: note: =eve: " + k.subs + "/=eve/a.bmp: not an image vkrt reads")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: graded 5 submissions x 4 scenes in ")) << r.output;
  EXPECT_TRUE(contains(r.output, ": 5 pass, 2 fail, 12 missing, 1 unreadable; report: " + report + "/index.html; exit status 5\n"))
      << r.output;

  // The figures for scripts, a row per comparison.
  const std::string csv = readFile(report + "/summary.csv");
  EXPECT_TRUE(contains(csv, "submission,scene,status,key_figure,max_channel_diff,")) << csv;
  EXPECT_TRUE(contains(csv, "alice,b,pass,0,0,0,inf,0,0,0,0,0,0,0,0,0,0,0," + k.subs + "/alice/hw/b.png,\n")) << csv;
  EXPECT_TRUE(contains(csv, "bob,a,fail,5,10,")) << csv;
  EXPECT_TRUE(contains(csv, "bob,b,missing,,,,,,,,,,,,,,,,,\n")) << csv;
  EXPECT_TRUE(contains(csv, "bob,c,fail,,,,,,,,,,,,,,,," + k.subs + "/bob/c.png,\"the image is 41x30, the reference 40x30\"\n"))
      << csv;
  EXPECT_TRUE(contains(csv, "bob,d,pass,2,10,")) << csv;
  EXPECT_TRUE(contains(csv, "carol,a,unreadable,")) << csv;
  EXPECT_TRUE(contains(csv, "\n'=eve,a,missing,")) << "a name a spreadsheet would run as a formula: " << csv;
  const std::string json = readFile(report + "/summary.json");
  EXPECT_TRUE(contains(json, "\"counts\": {\"pass\": 5, \"fail\": 2, \"missing\": 12, \"unreadable\": 1}")) << json;
  // Another size: no figures, rather than figures of nothing.
  EXPECT_TRUE(contains(json, "{\"scene\": \"c\", \"status\": \"fail\", \"image\": \"" + k.subs + "/bob/c.png\", \"page\": "
                             "\"pages/s0003-c003.html\", \"width\": 41, \"height\": 30, \"failures\": [")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"b\", \"reference\": \"" + k.refs + "/b.png\", \"width\": 32, \"height\": 24, "
                             "\"thresholds\": \"--max-diff 0\", \"key_figure\": \"largest difference (/255)\"}"))
      << json;
  EXPECT_TRUE(contains(json, "\"thresholds\": \"--max-pixels-over 2:3\"")) << json;

  // The pages (=eve first: the students in the order of their names, '=' before letters): the
  // overview names everyone; bob's a is boxed where it fails; the images are the submitted
  // ones; a missing image has no page.
  const std::string index = readFile(report + "/index.html");
  for (const char* name : {">alice<", ">bob<", ">carol<", ">ref_d<"}) EXPECT_EQ(contains(index, name), name != std::string(">ref_d<")) << name;
  EXPECT_TRUE(contains(index, ">d<br>")) << "the scene of ref_d.png is d";
  const std::string bobA = readFile(report + "/pages/s0003-c001.html");
  EXPECT_TRUE(contains(bobA, "5 pixels (0.1628%) differ by more than 2/255; allowed: 3 (--max-pixels-over 2:3)")) << bobA;
  EXPECT_TRUE(contains(bobA, "<span class=\"region\" style=\"left:0.000%;top:0.000%;width:25.000%;height:33.333%\"")) << bobA;
  EXPECT_EQ(readImage(report + "/images/s0003/c001.png").rgb, withOff(k.a, 5, 10).rgb);
  EXPECT_EQ(readImage(report + "/images/ref/c003.png").rgb, k.c.rgb);
  EXPECT_EQ(readImage(report + "/images/s0003/c001-thumb.png").width, 64);   // fits 96x72 already
  EXPECT_TRUE(fileExists(report + "/images/s0003/c001-diff.png"));
  // FLIP's map beside the heatmap, of the image's size, and its figures on the page and in the summary.
  EXPECT_EQ(readImage(report + "/images/s0003/c001-flip.png").width, k.a.width);
  EXPECT_TRUE(contains(bobA, "src=\"../images/s0003/c001-flip.png\"")) << bobA;
  EXPECT_TRUE(contains(bobA, "FLIP error (LDR-FLIP, mean 0.")) << bobA;
  EXPECT_TRUE(contains(bobA, "FLIP error: median, 95th, 99th percentile, max")) << bobA;
  EXPECT_TRUE(contains(json, "\"variance\": 0, \"flip\": {\"kind\": \"ldr\", \"mean\": 0, \"median\": 0, \"p95\": 0, \"p99\": 0, \"max\": 0}"))
      << json;
  EXPECT_FALSE(fileExists(report + "/pages/s0003-c002.html"));
  EXPECT_TRUE(fileExists(report + "/pages/s0004-c001.html"));   // carol's unreadable a
  // What it read is as it was; nothing temporary is left.
  EXPECT_EQ(readFile(k.subs + "/bob/a.png"), before);
  EXPECT_EQ(leftovers(k.dir), 0u);
}

// A folder of images is one submission, named for the folder; all passing: exit 0, and -q
// prints nothing.
TEST(GradeCli, ImagesSideBySideAreOneSubmission) {
  Class k = makeClass("grade/side-by-side");
  RunResult r = runVkrt("grade -q " + k.refs + " " + k.subs + "/alice/hw -o " + k.dir + "/report/");   // a new folder, named with '/'

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
  EXPECT_EQ(gpu.exitCode, 2) << "the scene's own status: " << gpu.output;
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
  fs::remove(k.dir + "/report/my-notes.txt");
  writeFile(k.dir + "/report/pages/notes.html", "mine\n");   // deeper in it
  refused(k.dir + "/report", "holds other files than a vkrt report");
  EXPECT_EQ(readFile(k.dir + "/report/pages/notes.html"), "mine\n");
  fs::remove(k.dir + "/report/pages/notes.html");
  fs::create_directories(k.dir + "/report/.vkrt-grade-abc123");   // what a killed run left: replaced with the rest
  EXPECT_EQ(runVkrt(grade + k.dir + "/report").exitCode, 5);
  EXPECT_FALSE(fs::exists(k.dir + "/report/.vkrt-grade-abc123"));
  EXPECT_TRUE(fileExists(k.dir + "/report/index.html"));
  EXPECT_EQ(leftovers(k.dir + "/report"), 0u);
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
  writeFile(k.dir + "/class.zip", "PK");
  usage(k.refs + " " + k.dir + "/class.zip -o " + k.dir + "/r", "is neither a folder of submissions nor a scene file (.test)");
  RunResult none = runVkrt("grade " + k.subs + " " + k.subs + "/alice -o " + k.dir + "/r");
  EXPECT_EQ(none.exitCode, 1) << none.output;
  EXPECT_TRUE(contains(none.output, "no reference image in '" + k.subs + "'")) << none.output;
  RunResult absent = runVkrt("grade " + k.dir + "/nothing " + k.subs + " -o " + k.dir + "/r");
  EXPECT_EQ(absent.exitCode, 4) << absent.output;
  EXPECT_TRUE(contains(absent.output, "the references '" + k.dir + "/nothing' are not a folder")) << absent.output;
  RunResult typo = runVkrt("grade " + k.refs + " " + k.dir + "/subz -o " + k.dir + "/r");
  EXPECT_EQ(typo.exitCode, 4) << typo.output;
  EXPECT_TRUE(contains(typo.output, "'" + k.dir + "/subz' does not exist (give a folder of submissions, or a scene file"))
      << typo.output;
  EXPECT_FALSE(fileExists(k.dir + "/r"));
  EXPECT_TRUE(contains(runVkrt("grad a b").output, "did you mean 'grade'?"));
}

// What a teacher of the course does: the ten course scenes rendered by vkrt (the Vulkan
// backend, in the grading run) and graded against references: the course's own for scene4-7
// (verified-matches) and, where the course published none (scene1-3), the CPU reference's.
// Tolerance: at most 30 pixels per scene off by more than 2/255, the Vulkan backend's
// agreement with those references (tests/gpu/gpu_render_test.cpp).
TEST(GradeCourse, TheTenCourseScenesRenderedAndGraded) {
  auto data = cse167Dir();
  if (!data) VKRT_SKIP_UNLESS_CI(kNoCse167Data);
  std::string dir = freshDir("grade/course");
  fs::create_directories(dir + "/refs");
  for (const auto& e : fs::directory_iterator(*data + "/verified-matches"))
    fs::copy_file(e.path(), dir + "/refs/" + e.path().filename().string());
  std::string scenes, course;
  for (int i = 1; i <= 3; ++i) course += " " + *data + "/scenes/scene" + std::to_string(i) + ".test";
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/refs/" + course).exitCode, 0);
  for (const char* s : {"scene1", "scene2", "scene3", "scene4-ambient", "scene4-diffuse", "scene4-emission",
                        "scene4-specular", "scene5", "scene6", "scene7"})
    scenes += " " + *data + "/scenes/" + s + ".test";
  RunResult r = runVkrt("grade --max-pixels-over 2:30 " + dir + "/refs" + scenes + " -o " + dir + "/report");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: vkrt                 10/10 pass\n")) << r.output;
  const std::string csv = readFile(dir + "/report/summary.csv");
  EXPECT_TRUE(contains(csv, "vkrt,scene7,pass,")) << csv;
  std::printf("%s", csv.c_str());
}

// --gradescope for a class: a test per student and scene, named for both, worth its points
// when it passes; the score their sum; the file written whole, never over what the run reads.
TEST(GradeCli, GradescopeResultsForAClass) {
  Class k = makeClass("grade/gradescope-class");
  const std::string results = k.dir + "/results.json";
  writeFile(k.dir + "/t.txt", "a --max-pixels-over 2:3 --points 4\nd --max-pixels-over 2:3 --points 0.5\n");
  RunResult r = runVkrt("grade " + k.refs + " " + k.subs + " -q -o " + k.dir + "/report --thresholds " + k.dir +
                        "/t.txt --gradescope " + results);
  EXPECT_EQ(r.exitCode, 5) << r.output;
  const std::string json = readFile(results);
  // alice passes a (4), b (1), c (1), d (0.5); bob d (0.5): 7.
  EXPECT_TRUE(contains(json, "{\"score\": 7, \"execution_time\": ")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"alice: a\", \"score\": 4, \"max_score\": 4, \"status\": \"passed\"")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"bob: a\", \"score\": 0, \"max_score\": 4, \"status\": \"failed\", \"output\": "
                             "\"fail (--max-pixels-over 2:3)\\u000a5 pixels")) << json;
  EXPECT_TRUE(contains(json, "where (pixels, x right and y down from the top left): (0,0)-(16,16)")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"bob: b\", \"score\": 0, \"max_score\": 1, \"status\": \"failed\", \"output\": "
                             "\"missing: the submission has no image for b")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"carol: a\", \"score\": 0, \"max_score\": 4, \"status\": \"failed\", \"output\": "
                             "\"unreadable: " + k.subs + "/carol/a.png\\u000acannot read image")) << json;
  EXPECT_TRUE(contains(json, "{\"name\": \"bob: d\", \"score\": 0.5, \"max_score\": 0.5, \"status\": \"passed\"")) << json;
  EXPECT_TRUE(contains(json, "bob: " + k.subs + "/bob/e.png: no reference image is named for this scene")) << json;

  // Never over what the run reads or the report it replaces; nothing written then.
  for (const std::string& refused : {k.refs + "/a.png", k.subs + "/alice/results.json", k.dir + "/t.txt",
                                     k.dir + "/report/results.json"}) {
    r = runVkrt("grade " + k.refs + " " + k.subs + " -q -o " + k.dir + "/report --thresholds " + k.dir +
                "/t.txt --gradescope " + refused);
    EXPECT_EQ(r.exitCode, 1) << refused << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "--gradescope " + refused + ": ")) << r.output;
    EXPECT_FALSE(fs::exists(k.subs + "/alice/results.json"));
  }
  r = runVkrt("grade " + k.refs + " " + k.subs + " -q -o " + k.dir + "/report2 --gradescope " + k.dir + "/no/such/r.json");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_FALSE(fs::exists(k.dir + "/report2"));
}

// Float images against a float reference are compared by HDR-FLIP, with the figure `vkrt diff`
// gives the same two files (diff's HDR-FLIP is matched with NVIDIA's in tests/compare); an
// 8-bit image against it, and anything against an 8-bit reference, by LDR-FLIP. A scene
// rendered in the run keeps its linear image for it too. The rest of the grade is the 8-bit
// images' either way.
TEST(GradeCli, FloatImagesAreComparedByHdrFlip) {
  std::string dir = freshDir("grade/hdr-flip");
  for (const char* f : {"refs", "ldr-refs", "class/hdr", "class/ldr"}) fs::create_directories(dir + "/" + f);
  const std::string scene = "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 2 2 4 3 3 3\ndiffuse 0.6 0.3 0.1\nsphere 0 0 0 1\n";
  writeFile(dir + "/ball.test", scene);
  writeFile(dir + "/dim.test", "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 2 2 4 2 2 2\ndiffuse 0.6 0.3 0.1\nsphere 0 0 0 1\n");
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/refs/ball.exr " + dir + "/ball.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/ldr-refs/ball.png " + dir + "/ball.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/class/hdr/ball.pfm " + dir + "/dim.test").exitCode, 0);
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/class/ldr/ball.png " + dir + "/dim.test").exitCode, 0);

  RunResult diff = runVkrt("diff --json " + dir + "/class/hdr/ball.pfm " + dir + "/refs/ball.exr");
  const std::string diffField = "\"flip\":{\"kind\":\"hdr\",\"mean\":";
  const std::size_t at = diff.output.find(diffField);
  ASSERT_NE(at, std::string::npos) << diff.output;
  const double expected = std::stod(diff.output.substr(at + diffField.size()));
  ASSERT_GT(expected, 0.01);

  RunResult r = runVkrt("grade -q " + dir + "/refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  const std::string json = readFile(dir + "/report/summary.json");
  const std::string field = "\"flip\": {\"kind\": \"hdr\", \"mean\": ";
  const std::size_t hdr = json.find(field);
  ASSERT_NE(hdr, std::string::npos) << json;
  EXPECT_NEAR(std::stod(json.substr(hdr + field.size())), expected, 1e-6) << json;
  EXPECT_TRUE(contains(json, "\"flip\": {\"kind\": \"ldr\"")) << "the PNG against the EXR: " << json;
  std::string pages;
  for (const auto& page : fs::directory_iterator(dir + "/report/pages")) pages += readFile(page.path().string());
  EXPECT_TRUE(contains(pages, "HDR-FLIP, 67 pixels per degree, exposures")) << "a comparison page says which FLIP";
  EXPECT_TRUE(contains(pages, "LDR-FLIP, 67 pixels per degree)"));

  // Another viewing condition (--pixels-per-degree): grade's HDR-FLIP is diff's there too.
  RunResult diff30 = runVkrt("diff --json --pixels-per-degree 30 " + dir + "/class/hdr/ball.pfm " + dir + "/refs/ball.exr");
  const std::size_t at30 = diff30.output.find(diffField);
  ASSERT_NE(at30, std::string::npos) << diff30.output;
  const double expected30 = std::stod(diff30.output.substr(at30 + diffField.size()));
  EXPECT_GT(std::fabs(expected30 - expected), 1e-3) << "the viewing condition changes FLIP";
  RunResult r30 = runVkrt("grade -q --pixels-per-degree 30 " + dir + "/refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(r30.exitCode, 5) << r30.output;
  const std::string json30 = readFile(dir + "/report/summary.json");
  ASSERT_NE(json30.find(field), std::string::npos) << json30;
  EXPECT_NEAR(std::stod(json30.substr(json30.find(field) + field.size())), expected30, 1e-6) << json30;
  std::string pages30;
  for (const auto& page : fs::directory_iterator(dir + "/report/pages")) pages30 += readFile(page.path().string());
  EXPECT_TRUE(contains(pages30, "HDR-FLIP, 30 pixels per degree, exposures")) << "the page says the condition";


  RunResult ldr = runVkrt("grade -q " + dir + "/ldr-refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(ldr.exitCode, 5) << ldr.output;
  EXPECT_FALSE(contains(readFile(dir + "/report/summary.json"), "\"kind\": \"hdr\"")) << "an 8-bit reference: LDR-FLIP";

  RunResult rendered = runVkrt("grade -q --backend cpu " + dir + "/refs " + dir + "/ball.test -o " + dir + "/report");
  EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
  EXPECT_TRUE(contains(readFile(dir + "/report/summary.json"), "\"flip\": {\"kind\": \"hdr\", \"mean\": 0,"))
      << readFile(dir + "/report/summary.json");
}

// A scene file beside the references says how its scene is graded (path-traced: by its noise;
// its gamma). One that cannot be read as a scene is said in a warning, with its first error
// at its line, and the scene is graded without it; -q leaves the warning out.
TEST(GradeCli, ASceneFileBesideTheReferencesThatCannotBeReadIsSaid) {
  std::string dir = freshDir("grade/broken-scene-file");
  for (const char* f : {"refs", "class/s1"}) fs::create_directories(dir + "/" + f);
  writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/refs/box.png");
  writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/class/s1/box.png");
  writeFile(dir + "/refs/box.test", "size 8 6\nintegrator pathtracer\nsphere 0 0\n");
  RunResult r = runVkrt("grade " + dir + "/refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: warning: grade: set aside: " + dir + "/refs/box.test:3: a scene file beside "
                                 "the references that cannot be read ('sphere' expects 4 arguments"))
      << r.output;
  EXPECT_TRUE(contains(r.output, "its scene is graded without it")) << r.output;
  RunResult quiet = runVkrt("grade -q " + dir + "/refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(quiet.exitCode, 0) << quiet.output;
  EXPECT_FALSE(contains(quiet.output, "warning")) << quiet.output;
  // Readable, it is used without a word.
  writeFile(dir + "/refs/box.test", "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nintegrator pathtracer\nsphere 0 0 0 1\n");
  RunResult fine = runVkrt("grade " + dir + "/refs " + dir + "/class -o " + dir + "/report");
  EXPECT_EQ(fine.exitCode, 0) << fine.output;
  EXPECT_FALSE(contains(fine.output, "warning")) << fine.output;
}

// Every input of the teacher's that grading does not use (a scene file beside the references
// that cannot be read, one with no reference, a file or folder there that is neither) is named
// where the teacher looks: on the terminal, at the top of the report, in summary.json (file,
// line, reason) and in Gradescope's results as a test only the staff see, worth nothing. With
// --strict the first is an error and nothing is graded or written.
TEST(GradeCli, TheTeachersInputsSetAsideAreNamedWhereTheTeacherLooks) {
  std::string dir = freshDir("grade/set-aside");
  for (const char* f : {"refs/extra", "class/s1"}) fs::create_directories(dir + "/" + f);
  for (const char* scene : {"box", "ball"}) {
    writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/refs/" + scene + ".png");
    writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/class/s1/" + scene + ".png");
  }
  writeFile(dir + "/refs/box.test", "size 8 6\nintegrator pathtracer\nsphere 0 0\n");   // line 3: an error
  writeFile(dir + "/refs/cornell.test", "size 8 6\n");   // no reference of its name
  writeFile(dir + "/refs/notes.txt", "my notes\n");
  writeFile(dir + "/refs/t.txt", "ball --max-diff 1\n");   // the thresholds file, kept here: used
  const std::string args = dir + "/refs " + dir + "/class --thresholds " + dir + "/refs/t.txt --gradescope " + dir +
                           "/results.json -o " + dir + "/report";
  RunResult r = runVkrt("grade " + args);
  EXPECT_EQ(r.exitCode, 0) << "set aside, graded without them: " << r.output;
  const std::string reasons[] = {
      dir + "/refs/box.test:3: a scene file beside the references that cannot be read ('sphere' expects 4 arguments",
      dir + "/refs/cornell.test: a scene file whose scene has no reference image (cornell.png, or another format",
      dir + "/refs/extra: a folder: the references are the images directly in '" + dir + "/refs'; not searched",
      dir + "/refs/notes.txt: neither an image vkrt reads"};
  for (const std::string& reason : reasons) EXPECT_TRUE(contains(r.output, "vkrt: warning: grade: set aside: " + reason)) << r.output;
  EXPECT_FALSE(contains(r.output, "t.txt: ")) << r.output;
  const std::string index = readFile(dir + "/report/index.html");
  EXPECT_TRUE(contains(index, "<h2>Set aside: 4 inputs of yours not used</h2>")) << index;
  EXPECT_TRUE(contains(index, "<code>" + dir + "/refs/box.test:3: a scene file")) << index;
  const std::string json = readFile(dir + "/report/summary.json");
  EXPECT_TRUE(contains(json, "\"set_aside\": [\n  {\"file\": \"" + dir + "/refs/cornell.test\", \"line\": 0, \"reason\": \"a scene file whose")) << json;
  EXPECT_TRUE(contains(json, "{\"file\": \"" + dir + "/refs/box.test\", \"line\": 3, \"reason\": \"a scene file beside "
                             "the references that cannot be read ('sphere' expects 4 arguments (x y z radius), got 2)")) << json;
  const std::string results = readFile(dir + "/results.json");
  EXPECT_TRUE(contains(results, "{\"score\": 2, ")) << results;
  EXPECT_TRUE(contains(results, "{\"name\": \"autograder configuration\", \"score\": 0, \"max_score\": 0, \"status\": "
                                "\"failed\", \"visibility\": \"hidden\", \"output\": \"The autograder's configuration "
                                "has inputs that were not used:\\u000a" + dir + "/refs/cornell.test: a scene file")) << results;

  // --strict: an error naming the first, nothing written.
  fs::remove_all(dir + "/report");
  fs::remove(dir + "/results.json");
  RunResult strict = runVkrt("grade --strict " + args);
  EXPECT_EQ(strict.exitCode, 1) << strict.output;
  EXPECT_TRUE(contains(strict.output, "vkrt: error: grade --strict: " + dir + "/refs/cornell.test: a scene file")) << strict.output;
  EXPECT_TRUE(contains(strict.output, "(and 3 more inputs set aside)")) << strict.output;
  EXPECT_FALSE(fs::exists(dir + "/report"));
  EXPECT_FALSE(fs::exists(dir + "/results.json"));
  // Mended, --strict grades and says nothing; summary.json's list is empty.
  for (const char* f : {"extra", "cornell.test", "notes.txt"}) fs::remove_all(dir + "/refs/" + f);
  writeFile(dir + "/refs/box.test", "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nintegrator pathtracer\nsphere 0 0 0 1\n");
  RunResult mended = runVkrt("grade --strict " + args);
  EXPECT_EQ(mended.exitCode, 0) << mended.output;
  EXPECT_FALSE(contains(mended.output, "set aside")) << mended.output;
  EXPECT_TRUE(contains(readFile(dir + "/report/summary.json"), "\"set_aside\": [],")) << readFile(dir + "/report/summary.json");
  EXPECT_FALSE(contains(readFile(dir + "/results.json"), "autograder configuration"));
}

// Only the student's own bytes are graded: a link (symbolic, absolute or relative, or hard) to
// a reference, a link out of the student's folder (to another student's image, through a
// linked folder: not searched, and noted) fails its scene saying what it is, in the report, the
// summaries and Gradescope's results; the student's own files beside them, and links inside
// the student's folder, are graded as before.
TEST(GradeCli, ALinkToAFileOutsideTheSubmissionFailsItsScene) {
  Class k = makeClass("grade/links");
  const std::string mallory = k.subs + "/mallory", trudy = k.subs + "/trudy";
  fs::create_directories(mallory);
  fs::create_directories(trudy + "/drafts");
  fs::create_symlink(k.refs + "/a.png", mallory + "/a.png");         // absolute, to the reference
  fs::create_symlink("../../refs/b.png", mallory + "/b.png");        // relative, to the reference
  writePngAtomic(k.c, mallory + "/C.png");                             // her own
  fs::create_symlink("../alice/d.png", mallory + "/d.png");          // another student's image
  fs::create_hard_link(k.refs + "/a.png", trudy + "/a.png");           // a hard link to the reference
  fs::create_symlink(k.subs + "/alice/hw", trudy + "/hw");             // a folder of another student's (b.png): not searched
  writePngAtomic(k.c, trudy + "/C.png");                               // his own
  writePngAtomic(k.d, trudy + "/drafts/final.png");
  fs::create_symlink("drafts/final.png", trudy + "/d.png");            // a link inside his folder: his own
  const std::string report = k.dir + "/report", results = k.dir + "/results.json";
  RunResult r = runVkrt("grade " + k.refs + " " + k.subs + " -o " + report + " --gradescope " + results);
  EXPECT_EQ(r.exitCode, 5) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: alice                4/4 pass\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: mallory              1/4 pass; unreadable: a, b, d\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: trudy                2/4 pass; missing: b; unreadable: a\n")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: note: trudy: " + trudy + "/hw: a link to a folder outside the submission ('" +
                                     k.subs + "/alice/hw'); not searched\n")) << r.output;
  const std::string json = readFile(report + "/summary.json");
  const std::string own = "; only the student's own files are graded";
  for (const std::string& why :
       {"'" + mallory + "/a.png' is the same file as the reference image '" + k.refs + "/a.png' (a link to it)" + own,
        "'" + mallory + "/b.png' is the same file as the reference image '" + k.refs + "/b.png' (a link to it)" + own,
        "'" + mallory + "/d.png' is a link to a file outside the submission ('" + k.subs + "/alice/d.png')" + own,
        "'" + trudy + "/a.png' is the same file as the reference image '" + k.refs + "/a.png' (a link to it)" + own}) {
    EXPECT_TRUE(contains(json, "\"status\": \"unreadable\", \"image\": ")) << json;
    EXPECT_TRUE(contains(json, "\"failures\": [\"" + why + "\"]")) << why << "\n" << json;
    EXPECT_TRUE(contains(readFile(report + "/summary.csv"), why)) << why;
    EXPECT_TRUE(contains(readFile(results), why)) << why;
  }
  EXPECT_TRUE(contains(readFile(results), "{\"name\": \"mallory: a\", \"score\": 0, \"max_score\": 1, \"status\": \"failed\""))
      << readFile(results);
  bool paged = false;   // the reason on the scene's page too
  for (const auto& e : fs::directory_iterator(report + "/pages"))
    paged = paged || contains(readFile(e.path().string()), "is a link to a file outside the submission");
  EXPECT_TRUE(paged);

  // A class folder of links to the students' folders grades as before, and so does a link to
  // one student's folder given alone.
  fs::create_directories(k.dir + "/linked");
  fs::create_symlink("../subs/alice", k.dir + "/linked/alice");
  fs::create_symlink(k.subs + "/trudy", k.dir + "/linked/trudy");
  RunResult linked = runVkrt("grade " + k.refs + " " + k.dir + "/linked -o " + report);
  EXPECT_EQ(linked.exitCode, 5) << linked.output;   // trudy's b missing (his link to alice's folder not searched)
  EXPECT_TRUE(contains(linked.output, "vkrt: alice                4/4 pass\n")) << linked.output;
  EXPECT_TRUE(contains(linked.output, "vkrt: trudy                2/4 pass; missing: b; unreadable: a\n")) << linked.output;
  RunResult one = runVkrt("grade -q --one-student " + k.refs + " " + k.dir + "/linked/alice -o " + report);
  EXPECT_EQ(one.exitCode, 0) << one.output;
}

// A scene file given to render that is the teacher's (a hard link to the scene file beside the
// references) or a link out of its folder is not rendered: its scene fails saying so.
TEST(GradeCli, ASceneFileThatIsNotTheStudentsIsNotRendered) {
  std::string dir = freshDir("grade/scene-links");
  for (const char* f : {"refs", "student", "elsewhere"}) fs::create_directories(dir + "/" + f);
  writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/refs/box.png");
  writePngAtomic(solid(8, 6, 10, 20, 30), dir + "/refs/ball.png");
  writeFile(dir + "/refs/box.test", "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\n");
  writeFile(dir + "/elsewhere/ball.test", "size 8 6\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\n");
  fs::create_hard_link(dir + "/refs/box.test", dir + "/student/box.test");
  fs::create_symlink("../elsewhere/ball.test", dir + "/student/ball.test");
  RunResult r = runVkrt("grade --backend cpu " + dir + "/refs " + dir + "/student/box.test " + dir +
                        "/student/ball.test -o " + dir + "/report");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: vkrt                 0/2 pass; unreadable: ball, box\n")) << r.output;
  EXPECT_FALSE(contains(r.output, "vkrt: rendered")) << r.output;
  const std::string json = readFile(dir + "/report/summary.json");
  EXPECT_TRUE(contains(json, "'" + dir + "/student/box.test' is the same file as the reference scene file '" + dir +
                             "/refs/box.test' (a link to it)")) << json;
  EXPECT_TRUE(contains(json, "'" + dir + "/student/ball.test' is a link to a file outside the submission ('" + dir +
                             "/elsewhere/ball.test')")) << json;
}

// Scene files that ask for more than a grader can give, among a good one: each fails its scene
// with a reason naming its limit, the good one passes, and the report and Gradescope's
// results are written. The runaway (a billion samples a pixel, the samples limit lifted for
// it in the thresholds file) is stopped by its time limit; the others are refused before they
// render: samples by the default limit, a size past the reference's, a maxdepth past 100.
TEST(GradeCli, ARunawaySceneFailsAtItsLimitAndTheOthersAreGraded) {
  std::string dir = freshDir("grade/limits");
  fs::create_directories(dir + "/refs");
  fs::create_directories(dir + "/student");
  const std::string box = "camera 0 -3 1 0 0 0.5 0 0 1 45\nquadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\n"
                          "vertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\n";
  writeFile(dir + "/student/ball.test", "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 0.2 0.4 0.6\nsphere 0 0 0 1\n");
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/refs/ball.png " + dir + "/student/ball.test").exitCode, 0);
  writeFile(dir + "/student/runaway.test", "size 40 30\nintegrator pathtracer\nspp 1000000000\nnexteventestimation on\n" + box);
  writeFile(dir + "/student/greedy.test", "size 40 30\nintegrator pathtracer\nspp 100000000\n" + box);
  const std::string whitted = "camera 0 -3 1 0 0 0.5 0 0 1 45\npoint 0 0 2 1 1 1\nspecular 0.5 0.5 0.5\nsphere 0 0 0 1\n";
  writeFile(dir + "/student/huge.test", "size 4000 3000\n" + whitted);
  writeFile(dir + "/student/deep.test", "size 40 30\nmaxdepth 1000000\n" + whitted);
  for (const char* scene : {"runaway", "greedy", "huge", "deep"})
    writePngAtomic(solid(40, 30, 1, 2, 3), dir + "/refs/" + scene + ".png");
  writeFile(dir + "/t.txt", "runaway --limit-time 1 --limit-spp 0\n");
  std::string scenes;
  for (const char* scene : {"ball", "runaway", "greedy", "huge", "deep"}) scenes += " " + dir + "/student/" + scene + ".test";
  for (const char* backend : {"vulkan", "cpu"}) {
    SCOPED_TRACE(backend);
    fs::remove_all(dir + "/report");
    fs::remove(dir + "/results.json");
    RunResult r = runVkrt("grade --backend " + std::string(backend) + " " + dir + "/refs" + scenes + " --thresholds " +
                          dir + "/t.txt --gradescope " + dir + "/results.json -o " + dir + "/report");
    EXPECT_EQ(r.exitCode, 5) << "fails, as a failing image does: " << r.output;
    EXPECT_TRUE(contains(r.output, "vkrt: vkrt                 1/5 pass; fail: deep, greedy, huge, runaway\n")) << r.output;
    const std::string json = readFile(dir + "/report/summary.json");
    for (const std::string& reason :
         {dir + "/student/runaway.test: not rendered within the time limit of 1 s (--limit-time)",
          dir + "/student/greedy.test: 100000000 samples per pixel, past the limit of 16384 (--limit-spp)",
          dir + "/student/huge.test: a 4000x3000 image (12000000 pixels) is past the limit of 1200 pixels (--limit-pixels)",
          dir + "/student/deep.test: maxdepth 1000000 is past the limit of 100 (--limit-depth)"}) {
      EXPECT_TRUE(contains(r.output, reason)) << reason << "\n" << r.output;
      EXPECT_TRUE(contains(json, reason)) << reason << "\n" << json;
    }
    const std::string results = readFile(dir + "/results.json");
    EXPECT_TRUE(contains(results, "{\"name\": \"ball\", \"score\": 1, \"max_score\": 1, \"status\": \"passed\"")) << results;
    EXPECT_TRUE(contains(results, "{\"name\": \"runaway\", \"score\": 0, \"max_score\": 1, \"status\": \"failed\", "
                                  "\"output\": \"fail")) << results;
    EXPECT_TRUE(contains(results, "time limit of 1 s (--limit-time)")) << results;
  }
}
