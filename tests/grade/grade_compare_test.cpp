// The parts of `vkrt grade` that decide: names matched to scenes, thresholds (from the
// command line and from a file), one image's grade against closed-form figures, the boxes
// around failing pixels, and thumbnails.
#include <gtest/gtest.h>

#include "util/errors.h"
#include "image/image_file.h"
#include "grade/grade_compare.h"
#include "grade/grade_inputs.h"
#include "grade/grade_report.h"
#include "grade/grade_thresholds.h"
#include "image/thumbnail.h"
#include "test_support.h"
#include "util/json.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

Image filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) im.pixel(x, y)[0] = r, im.pixel(x, y)[1] = g, im.pixel(x, y)[2] = b;
  return im;
}

GradeThresholds thresholds(const std::vector<std::pair<std::string, std::string>>& options) {
  GradeThresholds t;
  for (const auto& [name, value] : options) EXPECT_TRUE(applyThresholdOption(name, value, t)) << name;
  return t;
}

bool sameRect(const PixelRect& a, const PixelRect& b) {
  return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
}

}  // namespace

TEST(GradeNames, FileNamesMatchScenesWhateverTheCaseOrTheGradersPrefix) {
  EXPECT_EQ(sceneOfFileName("refs/ref_scene5.png", true), "scene5");
  EXPECT_EQ(sceneOfFileName("refs/REF-scene5.ppm", true), "scene5");
  EXPECT_EQ(sceneOfFileName("subs/ref_scene5.png"), "ref_scene5");   // a submission's: a copy of the reference
  EXPECT_EQ(sceneOfFileName("a/b/scene4-ambient.png"), "scene4-ambient");
  EXPECT_EQ(sceneOfFileName("ref_.png", true), "ref_");   // nothing after the prefix: the name itself
  EXPECT_EQ(sceneKey("Scene5"), sceneKey("scene5"));
  EXPECT_EQ(imageKindByName("x.PNG"), "PNG");
  EXPECT_EQ(imageKindByName("x.jpeg"), "JPEG");
  EXPECT_EQ(imageKindByName("dir.jpg/x.JPG"), "JPEG");
  EXPECT_FALSE(imageKindByName("x.test"));
}

TEST(GradeNames, ScenesSortAsPeopleCountThem) {
  std::vector<std::string> names{"scene10", "scene2", "Scene1", "scene4-specular", "scene4-ambient", "scene02"};
  std::sort(names.begin(), names.end(), naturalLess);
  EXPECT_EQ(names, (std::vector<std::string>{"Scene1", "scene2", "scene02", "scene4-ambient", "scene4-specular",
                                             "scene10"}));
}

// Every channel 3 steps above the reference: bias mean(ref - img) = -3 and variance 0 in
// closed form; the thresholds at the figure pass, below it fail.
TEST(GradeImage, BiasAndVarianceAgainstTheirClosedForm) {
  Image ref = filled(20, 10, 100, 50, 200), img = filled(20, 10, 103, 53, 203);
  Grade g = gradeImage(img, ref, thresholds({{"--max-bias", "3"}, {"--max-variance", "0"}}), nullptr);
  EXPECT_EQ(g.outcome, GradeOutcome::Pass) << (g.failures.empty() ? "" : g.failures[0]);
  EXPECT_DOUBLE_EQ(g.stats.bias, -3.0);
  EXPECT_DOUBLE_EQ(g.stats.variance, 0.0);
  EXPECT_EQ(g.maxDiff, 3);
  EXPECT_EQ(g.differing, 200);
  EXPECT_TRUE(g.regions.empty());   // judged by bias and variance: no pixel fails by itself
  Grade tight = gradeImage(img, ref, thresholds({{"--max-bias", "2.5"}}), nullptr);
  ASSERT_EQ(tight.outcome, GradeOutcome::Fail);
  EXPECT_NE(tight.failures[0].find("bias -3 exceeds 2.5"), std::string::npos) << tight.failures[0];
  EXPECT_EQ(tight.key.label, "bias");
  EXPECT_DOUBLE_EQ(tight.key.value, 3.0);
  // Half the pixels +4, half -4 (a checkerboard): bias 0, variance 16.
  Image noisy = ref;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x)
      for (int c = 0; c < 3; ++c) noisy.pixel(x, y)[c] = static_cast<std::uint8_t>(ref.pixel(x, y)[c] + ((x + y) % 2 ? 4 : -4));
  Grade n = gradeImage(noisy, ref, thresholds({{"--max-variance", "15.9"}}), nullptr);
  EXPECT_DOUBLE_EQ(n.stats.bias, 0.0);
  EXPECT_DOUBLE_EQ(n.stats.variance, 16.0);
  EXPECT_EQ(n.outcome, GradeOutcome::Fail);
  EXPECT_EQ(gradeImage(noisy, ref, thresholds({{"--max-variance", "16"}}), nullptr).outcome, GradeOutcome::Pass);
}

// The pixel thresholds of `vkrt diff`, the key figure they name, and with none at all: any
// difference fails.
TEST(GradeImage, PixelThresholdsAndTheKeyFigure) {
  Image ref = filled(40, 30, 10, 10, 10), img = ref;
  for (int x = 0; x < 5; ++x) img.pixel(x, 0)[1] = 20;   // 5 pixels 10 steps off
  Grade none = gradeImage(img, ref, GradeThresholds{}, nullptr);
  EXPECT_EQ(none.outcome, GradeOutcome::Fail);
  EXPECT_EQ(none.key.label, "pixels that differ");
  EXPECT_DOUBLE_EQ(none.key.value, 5);
  Grade five = gradeImage(img, ref, thresholds({{"--max-pixels-over", "2:5"}}), nullptr);
  EXPECT_EQ(five.outcome, GradeOutcome::Pass);
  EXPECT_EQ(five.key.label, "pixels over 2/255");
  EXPECT_EQ(five.key.text, "5 (0.417%)");
  EXPECT_EQ(gradeImage(img, ref, thresholds({{"--max-pixels-over", "2:4"}}), nullptr).outcome, GradeOutcome::Fail);
  EXPECT_EQ(gradeImage(img, ref, thresholds({{"--max-pixels-over", "10:0"}}), nullptr).outcome, GradeOutcome::Pass);
  Grade diff = gradeImage(img, ref, thresholds({{"--max-diff", "9"}}), nullptr);
  EXPECT_EQ(diff.outcome, GradeOutcome::Fail);
  EXPECT_DOUBLE_EQ(diff.key.value, 10);
  // Another size fails, whatever the thresholds.
  Grade size = gradeImage(filled(41, 30, 10, 10, 10), ref, thresholds({{"--max-diff", "255"}}), nullptr);
  EXPECT_EQ(size.outcome, GradeOutcome::Fail);
  EXPECT_EQ(size.failures[0], "the image is 41x30, the reference 40x30");
}

// --max-flip: the mean LDR-FLIP error of the two 8-bit images, its key figure, its text in the
// thresholds and a thresholds file.
TEST(GradeImage, MaxFlipJudgesTheMeanFlipError) {
  Image ref = filled(40, 30, 10, 10, 10), img = ref;
  for (int x = 0; x < 40; ++x) img.pixel(x, 15)[1] = 200;   // a green line
  FlipMap map;
  Grade loose = gradeImage(img, ref, thresholds({{"--max-flip", "0.5"}}), nullptr, &map);
  const double mean = flipStats(ldrFlip(img, ref)).mean;
  ASSERT_GT(mean, 0.01);
  EXPECT_DOUBLE_EQ(loose.flip.mean, mean);
  EXPECT_EQ(loose.outcome, GradeOutcome::Pass);
  EXPECT_EQ(loose.key.label, "mean FLIP error");
  EXPECT_DOUBLE_EQ(loose.key.value, mean);
  EXPECT_EQ(map.error.size(), 40u * 30u);
  Grade tight = gradeImage(img, ref, thresholds({{"--max-flip", "0.01"}}), nullptr);
  EXPECT_EQ(tight.outcome, GradeOutcome::Fail);
  ASSERT_EQ(tight.failures.size(), 1u);
  EXPECT_NE(tight.failures[0].find("LDR-FLIP mean error"), std::string::npos) << tight.failures[0];
  EXPECT_EQ(thresholds({{"--max-flip", "0.05"}}).text(), "--max-flip 0.05");
  GradeThresholds t;
  EXPECT_THROW(applyThresholdOption("--max-flip", "2", t), UsageError);
  EXPECT_DOUBLE_EQ(gradeImage(ref, ref, GradeThresholds{}, nullptr).flip.max, 0.0);
}

// Two blobs of failing pixels, one of them two squares that touch at a corner: two boxes,
// the one with more pixels first, each the bounding box of its squares (cut at the image's
// edge); pixels under the step are no region; the limit keeps the largest.
TEST(GradeRegions, BoxesAroundTheFailingPixels) {
  Image ref = filled(90, 40, 0, 0, 0), img = ref;
  img.pixel(3, 3)[0] = 50;                                   // square (0,0)
  img.pixel(17, 17)[0] = 50, img.pixel(18, 18)[0] = 50;      // square (1,1): touches (0,0) at a corner
  for (int x = 75; x < 90; ++x) img.pixel(x, 35)[2] = 90;    // squares (4,2) and (5,2), the latter cut at 90
  img.pixel(75, 3)[1] = 2;                                   // under the step: no region
  Grade g = gradeImage(img, ref, thresholds({{"--max-pixels-over", "2:0"}}), nullptr);
  ASSERT_EQ(g.outcome, GradeOutcome::Fail);
  ASSERT_EQ(g.regions.size(), 2u);
  EXPECT_TRUE(sameRect(g.regions[0], {64, 32, 90, 40})) << g.regions[0].x0 << "," << g.regions[0].y0;   // 15 pixels
  EXPECT_TRUE(sameRect(g.regions[1], {0, 0, 32, 32}));                                                  // 3 pixels
  EXPECT_EQ(g.moreRegions, 0);
  ImageDiff d = compare(img, ref);
  long long more = -1;
  std::vector<PixelRect> one = failingRegions(d, 2, 16, 1, &more);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(sameRect(one[0], {64, 32, 90, 40}));
  EXPECT_EQ(more, 1);
  std::vector<PixelRect> all = failingRegions(d, 1, 16, 10, nullptr);   // the 2-step pixel at step 1: a third box
  ASSERT_EQ(all.size(), 3u);
  EXPECT_TRUE(sameRect(all[2], {64, 0, 80, 16}));
  EXPECT_TRUE(gradeImage(ref, ref, GradeThresholds{}, nullptr).regions.empty());
}

TEST(GradeThresholdFile, EachSceneItsOwnLineElseTheCommandLine) {
  std::string dir = freshDir("grade/thresholds");
  writeFile(dir + "/t.txt", "# scene   options\n\nScene7 --max-pixels-over 2:0.1%   # the dragon\ncornellNEE --max-bias=0.5 --max-variance 250\n");
  GradeThresholds all = thresholds({{"--max-diff", "4"}});
  ThresholdTable table = readThresholdFile(dir + "/t.txt", all, {"scene7", "cornellnee", "scene6"});
  EXPECT_EQ(table.forScene("scene7").text(), "--max-pixels-over 2:0.1%");
  EXPECT_EQ(table.forScene("cornellnee").text(), "--max-bias 0.5 --max-variance 250");
  EXPECT_EQ(table.forScene("scene6").text(), "--max-diff 4");
  EXPECT_EQ(GradeThresholds{}.text(), "any difference fails");
}

// The limits on a scene file's render: the command line's, and a line's replacing only those
// it names; a line of limits alone keeps the command line's thresholds (and a line of
// thresholds the command line's limits).
TEST(GradeThresholdFile, ALinesLimitsReplaceOnlyThoseItNames) {
  std::string dir = freshDir("grade/thresholds-limits");
  writeFile(dir + "/t.txt", "scene7 --limit-time 90 --limit-depth 0\ncornellNEE --max-bias 0.5 --limit-spp 64\nscene5 --max-diff 1\n");
  GradeThresholds all = thresholds({{"--max-diff", "4"}, {"--limit-time", "10"}, {"--limit-pixels", "5000"}});
  ThresholdTable table = readThresholdFile(dir + "/t.txt", all, {"scene7", "cornellnee", "scene5", "scene6"});
  const GradeThresholds& s7 = table.forScene("scene7");
  EXPECT_EQ(s7.text(), "--max-diff 4");   // the command line's
  EXPECT_EQ(s7.limits.seconds, 90.0);
  EXPECT_EQ(s7.limits.depth, 0);
  EXPECT_EQ(s7.limits.pixels, 5000u);
  EXPECT_FALSE(s7.limits.spp);
  const GradeThresholds& nee = table.forScene("cornellnee");
  EXPECT_EQ(nee.text(), "--max-bias 0.5");
  EXPECT_EQ(nee.limits.seconds, 10.0);
  EXPECT_EQ(nee.limits.spp, 64u);
  EXPECT_EQ(table.forScene("scene5").limits.seconds, 10.0);
  EXPECT_EQ(table.forScene("scene6").limits.pixels, 5000u);
  EXPECT_FALSE(table.forScene("scene6").limits.depth);
}

TEST(GradeThresholdFile, AByteOrderMarkIsNotPartOfTheFirstScene) {
  std::string dir = freshDir("grade/thresholds-bom");
  writeFile(dir + "/t.txt", "\xEF\xBB\xBFscene6 --max-diff 2\r\n");
  EXPECT_EQ(readThresholdFile(dir + "/t.txt", GradeThresholds{}, {"scene6"}).forScene("scene6").text(), "--max-diff 2");
}

// A thresholds file that cannot be read is an I/O error that says why, as an image's does.
TEST(GradeThresholdFile, AnUnreadableOneSaysWhy) {
  std::string dir = freshDir("grade/thresholds-unreadable");
  auto error = [&](const std::string& path) {
    try {
      readThresholdFile(path, GradeThresholds{}, {"scene6"});
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(dir + "/none.txt"), "cannot read the thresholds file '" + dir + "/none.txt': No such file or directory");
  EXPECT_EQ(error(dir), "cannot read the thresholds file '" + dir + "': Is a directory");
}

TEST(GradeThresholdFile, ASceneNameWithSpacesInQuotes) {
  std::string dir = freshDir("grade/thresholds-quoted");
  writeFile(dir + "/t.txt", "\"my scene 2\"   --max-diff 3\n\"scene6\"--max-diff=1\n");
  ThresholdTable t = readThresholdFile(dir + "/t.txt", GradeThresholds{}, {"my scene 2", "scene6"});
  EXPECT_EQ(t.forScene("my scene 2").text(), "--max-diff 3");
  EXPECT_EQ(t.forScene("scene6").text(), "--max-diff 1");
  writeFile(dir + "/t.txt", "\"my scene 2 --max-diff 3\n");
  EXPECT_THROW(readThresholdFile(dir + "/t.txt", GradeThresholds{}, {"my scene 2"}), UsageError);
}

// What tells a report folder from a folder of someone's files: only the paths a report writes.
TEST(GradeReportFolder, OnlyTheReportsOwnPaths) {
  for (const char* p : {"index.html", "grade.js", "summary.json", "pages", "pages/s0001-c001.html", "pages/s12345-c999.html",
                        "images", "images/ref", "images/ref/c003.png", "images/s0002", "images/s0002/c001.png",
                        "images/s0002/c001-thumb.png", "images/s0002/c010-diff.png", ".vkrt-grade-x1Y2z3/anything"})
    EXPECT_TRUE(isReportPath(p)) << p;
  for (const char* p : {"notes.txt", "pages/notes.html", "pages/s0001-c001.htm", "pages/s-c1.html", "images/ref/c1.jpg",
                        "images/s0002/c001-other.png", "images/s0002/x", "images/sx", "imagesx", "pages/s0001-c001.html/x"})
    EXPECT_FALSE(isReportPath(p)) << p;
}

// JSON of any bytes is JSON: what is not UTF-8 becomes U+FFFD; UTF-8 stays as it is.
TEST(GradeReportFolder, SummaryStringsAreValidJsonWhateverTheBytes) {
  EXPECT_EQ(jsonQuoted("bad\xffname"), "\"bad\\ufffdname\"");
  EXPECT_EQ(jsonQuoted("Jos\xc3\xa9"), "\"Jos\xc3\xa9\"");
  EXPECT_EQ(jsonQuoted("\xe2\x82"), "\"\\ufffd\\ufffd\"");   // cut short
  EXPECT_EQ(jsonQuoted("\xc0\xaf"), "\"\\ufffd\\ufffd\"");   // overlong
  EXPECT_EQ(jsonQuoted("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");   // a surrogate
  EXPECT_EQ(jsonQuoted("\xf0\x9f\x98\x80 \"q\"\n"), "\"\xf0\x9f\x98\x80 \\\"q\\\"\\u000a\"");
}

TEST(GradeThresholdFile, ABadLineIsAnErrorAtItsLine) {
  std::string dir = freshDir("grade/thresholds-bad");
  auto error = [&](const std::string& text) {
    writeFile(dir + "/t.txt", text);
    try {
      readThresholdFile(dir + "/t.txt", GradeThresholds{}, {"scene6", "scene7"});
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string at = dir + "/t.txt:";
  EXPECT_EQ(error("scene6 --max-diff 2\nscene9 --max-diff 2\n"), at + "2: no reference image for the scene 'scene9'");
  EXPECT_EQ(error("scene6 --max-diff 2\n\nSCENE6 --max-diff 3\n"), at + "3: the scene 'SCENE6' was given on line 1");
  EXPECT_EQ(error("scene7 --max-diff 300\n"), at + "1: --max-diff expects an integer from 0 to 255, got '300'");
  EXPECT_EQ(error("scene7 --max-bias -1\n"), at + "1: --max-bias expects a number of 0 or more (8-bit units), got '-1'");
  EXPECT_EQ(error("scene7 --max-pixel 2:1\n"),
            at + "1: unknown threshold or limit '--max-pixel' (expected --max-pixels-over, --max-diff, --max-flip, "
                 "--max-bias, --max-variance, --max-bias-z, --pixels-per-degree, --points, --limit-time, --limit-spp, "
                 "--limit-pixels or --limit-depth)");
  EXPECT_EQ(error("scene7 --limit-spp -3\n"),
            at + "1: --limit-spp expects a whole number from 0 (no limit) to 1099511627776, got '-3'");
  EXPECT_EQ(error("scene7 --limit-depth 1e3\n"),
            at + "1: --limit-depth expects a whole number from 0 (no limit) to 1000000, got '1e3'");
  EXPECT_EQ(error("scene7 --limit-time soon\n"),
            at + "1: --limit-time expects a number of 0 or more (seconds; 0: no limit), got 'soon'");
  EXPECT_EQ(error("scene7 --max-bias-z x\n"), at + "1: --max-bias-z expects a number of 0 or more (standard errors), got 'x'");
  EXPECT_EQ(error("scene7 --max-diff\n"), at + "1: '--max-diff' needs a value");
  EXPECT_EQ(error("scene7\n"), at + "1: no threshold for scene7 (e.g. --max-pixels-over 2:0.1%)");
  EXPECT_THROW(readThresholdFile(dir + "/absent.txt", GradeThresholds{}, {}), IoError);
}

// A thumbnail fits its box, keeps the shape, and each pixel is the mean of those it covers.
TEST(Thumbnail, FitsItsBoxAndAveragesWhatItCovers) {
  Image im(8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x) im.pixel(x, y)[0] = static_cast<std::uint8_t>(x < 4 ? 0 : 200), im.pixel(x, y)[1] = static_cast<std::uint8_t>(10 * y);
  Image t = thumbnail(im, 2, 2);
  ASSERT_EQ(t.width, 2);
  ASSERT_EQ(t.height, 1);
  EXPECT_EQ(t.pixel(0, 0)[0], 0);
  EXPECT_EQ(t.pixel(1, 0)[0], 200);
  EXPECT_EQ(t.pixel(0, 0)[1], 15);   // rows 0..3: 0, 10, 20, 30
  Image big = thumbnail(gradient(640, 480), 96, 72);
  EXPECT_EQ(big.width, 96);
  EXPECT_EQ(big.height, 72);
  Image small = thumbnail(im, 96, 72);   // fits already: as it is
  EXPECT_EQ(small.rgb, im.rgb);
}
