// `vkrt diff` and `vkrt SCENE --check`: metrics with known answers, thresholds and their exit
// statuses (0 pass, 5 differ, 1 usage, 4 unreadable), JSON, and the heatmap.
#include <cstdio>

#include <gtest/gtest.h>

#include "compare/image_check.h"
#include "cli/options.h"
#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// A 10x10 grey image, and the same with `changed` pixels raised by `by` in red.
Image grey() {
  Image img(10, 10);
  std::fill(img.rgb.begin(), img.rgb.end(), 100);
  return img;
}
Image changed(int count, int by) {
  Image img = grey();
  for (int i = 0; i < count; ++i) img.pixel(i % 10, i / 10)[0] = static_cast<std::uint8_t>(100 + by);
  return img;
}

}  // namespace

TEST(ImageCheck, MetricsHaveTheirKnownValues) {
  ImageDiff d = compare(changed(1, 30), grey());
  // One channel of 300 differs by 30: RMSE = sqrt(900 / 300) = sqrt(3).
  EXPECT_NEAR(d.rmse, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(d.psnr(), 20.0 * std::log10(255.0 / std::sqrt(3.0)), 1e-9);
  EXPECT_EQ(d.maxChannelDiff, 30);
  EXPECT_TRUE(std::isinf(compare(grey(), grey()).psnr()));
}

TEST(ImageCheck, ThresholdsParseAndDecide) {
  PixelThreshold t = parsePixelThreshold("2:0.1%");
  EXPECT_EQ(t.steps, 2);
  EXPECT_DOUBLE_EQ(t.limit, 0.1);
  EXPECT_TRUE(t.percent);
  for (const char* bad : {"2", "x:1", "2:", "2:-1", "2:101%", "300:1", "2:1x"})
    EXPECT_THROW(parsePixelThreshold(bad), UsageError) << bad;

  ImageDiff d = compare(changed(5, 3), grey());   // 5 of 100 pixels off by 3
  const FlipStats noFlip;
  CheckThresholds none;
  EXPECT_EQ(failedThresholds(d, noFlip, none).size(), 1u) << "no threshold: any difference fails";
  CheckThresholds count{{parsePixelThreshold("2:5")}, -1};
  EXPECT_TRUE(failedThresholds(d, noFlip, count).empty());
  CheckThresholds fewer{{parsePixelThreshold("2:4")}, -1};
  EXPECT_EQ(failedThresholds(d, noFlip, fewer).size(), 1u);
  CheckThresholds share{{parsePixelThreshold("2:5%")}, -1};
  EXPECT_TRUE(failedThresholds(d, noFlip, share).empty());
  CheckThresholds smallerShare{{parsePixelThreshold("2:4.9%")}, -1};
  EXPECT_EQ(failedThresholds(d, noFlip, smallerShare).size(), 1u);
  CheckThresholds steps{{parsePixelThreshold("3:0")}, -1};
  EXPECT_TRUE(failedThresholds(d, noFlip, steps).empty()) << "off by 3 is not more than 3";
  CheckThresholds maxDiff{{}, 2};
  EXPECT_EQ(failedThresholds(d, noFlip, maxDiff).size(), 1u);

  // --max-flip judges the mean FLIP error alone: a mean above X fails, one equal to it passes.
  FlipStats flip;
  flip.mean = 0.25;
  CheckThresholds maxFlip;
  maxFlip.maxFlip = parseFlipThreshold("0.25");
  EXPECT_TRUE(failedThresholds(d, flip, maxFlip).empty()) << "0.25 does not exceed 0.25";
  maxFlip.maxFlip = parseFlipThreshold("0.2");
  ASSERT_EQ(failedThresholds(d, flip, maxFlip).size(), 1u);
  EXPECT_NE(failedThresholds(d, flip, maxFlip)[0].find("(--max-flip)"), std::string::npos);
  for (const char* bad : {"", "-0.1", "1.5", "x", "0.1x", "nan"})
    EXPECT_THROW(parseFlipThreshold(bad), UsageError) << bad;
}

TEST(ImageCheck, HeatmapColoursAndLegend) {
  ImageDiff d = compare(changed(2, 40), grey());
  Image heat = differenceHeatmap(d, 16);
  EXPECT_EQ(heat.width, 10);
  EXPECT_EQ(heat.height, 10 + 12);   // the legend strip
  const std::uint8_t* red = heat.pixel(0, 0);   // 40 >= 16: red
  EXPECT_EQ(red[0], 255);
  EXPECT_EQ(red[1], 0);
  EXPECT_EQ(heat.pixel(5, 5)[0] + heat.pixel(5, 5)[1] + heat.pixel(5, 5)[2], 0) << "equal pixels are black";
  const std::uint8_t* rampStart = heat.pixel(0, 10 + 2);   // the legend's ramp begins blue
  EXPECT_EQ(rampStart[2], 255);
  EXPECT_EQ(rampStart[0], 0);
}

TEST(DiffCli, ExitStatusesJsonAndHeatmap) {
  std::string dir = freshDir("diff-cli");
  writePngAtomic(grey(), dir + "/a.png");
  writePngAtomic(changed(5, 3), dir + "/b.png");
  writePngAtomic(Image(4, 4), dir + "/small.png");
  EXPECT_EQ(runVkrt("diff " + dir + "/a.png " + dir + "/a.png").exitCode, 0);
  RunResult any = runVkrt("diff " + dir + "/a.png " + dir + "/b.png");
  EXPECT_EQ(any.exitCode, 5) << any.output;
  EXPECT_NE(any.output.find("over 2/255  5 pixels (5%)"), std::string::npos) << any.output;
  EXPECT_EQ(runVkrt("diff --max-pixels-over 2:5% " + dir + "/a.png " + dir + "/b.png").exitCode, 0);
  EXPECT_EQ(runVkrt("diff --max-pixels-over 2:4 " + dir + "/a.png " + dir + "/b.png").exitCode, 5);
  EXPECT_EQ(runVkrt("diff --max-pixels-over 1:100% --max-diff 2 " + dir + "/a.png " + dir + "/b.png").exitCode, 5);
  RunResult json = runVkrt("diff --json --max-diff 3 " + dir + "/a.png " + dir + "/b.png");
  EXPECT_EQ(json.exitCode, 0) << json.output;
  EXPECT_NE(json.output.find("\"max_channel_diff\":3,\"pixels_differing\":5,\"pixels_over_1\":5,\"share_over_1\":0.05"),
            std::string::npos)
      << json.output;
  EXPECT_NE(json.output.find("\"pass\":true"), std::string::npos) << json.output;
  RunResult heat = runVkrt("diff --diff " + dir + "/heat.png " + dir + "/a.png " + dir + "/b.png");
  EXPECT_EQ(heat.exitCode, 5);
  EXPECT_EQ(readImage(dir + "/heat.png").height, 22);
  EXPECT_EQ(runVkrt("diff " + dir + "/a.png " + dir + "/small.png").exitCode, 5) << "sizes differ";
  EXPECT_EQ(runVkrt("diff " + dir + "/a.png " + dir + "/missing.png").exitCode, 4);
  EXPECT_EQ(runVkrt("diff " + dir + "/a.png").exitCode, 1);
  EXPECT_EQ(runVkrt("diff --max-pixels-over 2 " + dir + "/a.png " + dir + "/b.png").exitCode, 1);
  EXPECT_EQ(runVkrt("--json " + sourcePath("scenes/spheres.test")).exitCode, 1) << "--json needs --check";
}

TEST(DiffCli, CheckRendersThenCompares) {
  std::string dir = freshDir("check-cli");
  std::string scene = sourcePath("scenes/spheres.test");
  ASSERT_EQ(runVkrt("-q --backend cpu -o " + dir + "/ref.png " + scene).exitCode, 0);
  RunResult same = runVkrt("-q --backend cpu -o " + dir + "/out.png --check " + dir + "/ref.png " + scene);
  EXPECT_EQ(same.exitCode, 0) << same.output;
  EXPECT_NE(same.output.find("PASS"), std::string::npos);
  // A reference with a changed pixel: fails without a threshold, passes with one.
  Image ref = readImage(dir + "/ref.png");
  ref.pixel(3, 3)[1] = static_cast<std::uint8_t>(ref.pixel(3, 3)[1] ^ 0x40);
  writePngAtomic(ref, dir + "/ref2.png");
  std::remove((dir + "/out.png").c_str());
  RunResult differs = runVkrt("-q --backend cpu -o " + dir + "/out.png --check " + dir + "/ref2.png " + scene);
  EXPECT_EQ(differs.exitCode, 5) << differs.output;
  // (README, "Exit status": the one case of a non-zero status with an image written)
  EXPECT_TRUE(fileExists(dir + "/out.png")) << "the render is written whatever the comparison says";
  EXPECT_EQ(runVkrt("-q --backend cpu -o " + dir + "/out.png --check " + dir + "/ref2.png --max-pixels-over 2:1 " + scene)
                .exitCode,
            0);
}

TEST(DiffCli, CompareRendersWithBothBackendsAndReportsTheirDifference) {
  VKRT_REQUIRE_GPU(context);
  std::string dir = freshDir("compare-cli");
  RunResult r = runVkrt("--compare --json --diff " + dir + "/heat.png --max-pixels-over 2:0.1% " +
                        sourcePath("scenes/spheres.test"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* key : {"{\"scene\":", "\"vulkan\":{\"backend\":\"vulkan (", "\"cpu\":{\"backend\":\"cpu\"",
                          "\"first_dispatch_s\":", "\"difference\":{\"width\":64,\"height\":48,\"rmse\":",
                          "\"pass\":true", "\"flip\":{\"kind\":\"hdr\""})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
  EXPECT_EQ(readImage(dir + "/heat.png").width, 64);
  RunResult text = runVkrt("--compare -q " + sourcePath("scenes/spheres.test"));
  EXPECT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("vulkan vs cpu:"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("PSNR"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("HDR-FLIP mean"), std::string::npos) << "the renders' radiance compared: " << text.output;
}
