// Every format vkrt writes, read back by the command line: `vkrt convert` between PNG, PPM,
// PFM and EXR (float to 8-bit with the recorded gamma gives the bytes the render wrote;
// 8-bit to float and back gives the same bytes; float to float the same bits and records),
// `vkrt diff` of float images (the linear difference beside the 8-bit figures), --check
// against a float reference, and the files convert refuses to touch.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "image/image_file.h"
#include "image/image_read.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// A path-traced scene (gamma 2.2, recorded in the image's vkrt-samples record), on the CPU
// reference: its float and 8-bit outputs of one render.
const char* kPathScene =
    "size 24 18\ncamera 0 -3 1 0 0 0.5 0 0 1 45\nintegrator pathtracer\nspp 4\ngamma 2.2\n"
    "nexteventestimation on\nquadLight -0.5 -0.5 2 1 0 0 0 1 0 4 4 4\ndiffuse 0.7 0.5 0.3\n"
    "vertex -3 -3 0\nvertex 3 -3 0\nvertex 3 3 0\nvertex -3 3 0\ntri 0 1 2\ntri 0 2 3\nsphere 0 0 0.5 0.5\n";

struct Renders {
  std::string dir;
};

// The scene rendered once per format, with the same seed (the same floats each time).
Renders renderAll(const std::string& name) {
  Renders r{freshDir("cli-convert/" + name)};
  writeFile(r.dir + "/s.test", kPathScene);
  for (const char* ext : {"png", "ppm", "pfm", "exr"}) {
    RunResult run = runVkrt("--backend cpu -q --seed 5 -o " + r.dir + "/render." + ext + " " + r.dir + "/s.test");
    EXPECT_EQ(run.exitCode, 0) << run.output;
  }
  return r;
}

}  // namespace

TEST(CliConvert, FloatToBytesIsTheRendersOwnEncoding) {
  Renders r = renderAll("float-to-bytes");
  for (const char* from : {"pfm", "exr"})
    for (const char* to : {"png", "ppm"}) {
      const std::string out = r.dir + "/from-" + from + "." + to;
      RunResult run = runVkrt("convert " + r.dir + "/render." + from + " " + out);
      ASSERT_EQ(run.exitCode, 0) << run.output;
      EXPECT_NE(run.output.find("vkrt: wrote " + out), std::string::npos) << run.output;
      EXPECT_EQ(readImage(out).rgb, readImage(r.dir + "/render." + to).rgb) << from << " -> " << to;
      EXPECT_EQ(recordedGamma(readImageFileText(out)), 2.2) << "the record travels: " << out;
    }
}

TEST(CliConvert, FloatToFloatKeepsEveryBitAndRecord) {
  Renders r = renderAll("float-to-float");
  ASSERT_EQ(runVkrt("convert " + r.dir + "/render.exr " + r.dir + "/again.pfm").exitCode, 0);
  ASSERT_EQ(runVkrt("convert " + r.dir + "/render.pfm " + r.dir + "/again.exr").exitCode, 0);
  const RadianceImage pfm = readFloatImage(r.dir + "/render.pfm");
  EXPECT_TRUE(sameBits(readFloatImage(r.dir + "/render.exr"), pfm));   // the render, either way
  for (const char* name : {"/again.pfm", "/again.exr"}) {
    const RadianceImage back = readFloatImage(r.dir + name);
    EXPECT_TRUE(sameBits(back, pfm)) << name;
    ImageRecords sorted = pfm.text, backSorted = back.text;   // an EXR header sorts its attributes by name
    std::sort(sorted.begin(), sorted.end());
    std::sort(backSorted.begin(), backSorted.end());
    EXPECT_EQ(backSorted, sorted) << name;
  }
}

TEST(CliConvert, BytesToFloatAndBackGiveTheSameBytes) {
  Renders r = renderAll("bytes-round-trip");
  for (const char* from : {"png", "ppm"})
    for (const char* via : {"pfm", "exr"}) {
      const std::string mid = r.dir + "/" + from + "-via." + via, back = r.dir + "/" + from + "-" + via + "-back.png";
      ASSERT_EQ(runVkrt("convert " + r.dir + "/render." + from + " " + mid).exitCode, 0);
      ASSERT_EQ(runVkrt("convert " + mid + " " + back).exitCode, 0);
      EXPECT_EQ(readImage(back).rgb, readImage(r.dir + "/render." + from).rgb) << from << " via " << via;
      // Decoded with gamma 2.2: a mid-grey byte is far below half in radiance.
      const RadianceImage linear = readFloatImage(mid);
      const Image bytes = readImage(r.dir + "/render." + from);
      for (std::size_t i = 0; i < bytes.rgb.size(); ++i)
        if (bytes.rgb[i] == 128) {
          EXPECT_NEAR(linear.rgb[i], std::pow(128.5 / 255.0, 2.2), 1e-6);
        }
    }
}

TEST(CliConvert, DiffReadsEveryFormatAndReportsTheLinearDifferenceOfFloats) {
  Renders r = renderAll("diff");
  RunResult same = runVkrt("diff " + r.dir + "/render.pfm " + r.dir + "/render.exr");
  EXPECT_EQ(same.exitCode, 0) << same.output;
  EXPECT_NE(same.output.find("linear      max diff 0, RMSE 0"), std::string::npos) << same.output;
  RunResult mixed = runVkrt("diff " + r.dir + "/render.exr " + r.dir + "/render.png");
  EXPECT_EQ(mixed.exitCode, 0) << mixed.output;   // the float image encoded as the PNG was
  EXPECT_EQ(mixed.output.find("linear"), std::string::npos) << mixed.output;
  // One channel of one pixel changed by 0.25 in radiance.
  RadianceImage changed = readFloatImage(r.dir + "/render.pfm");
  changed.pixel(3, 2)[1] += 0.25f;
  writeImageAtomic(changed, r.dir + "/changed.exr", 2.2);
  RunResult differs = runVkrt("diff --json " + r.dir + "/render.pfm " + r.dir + "/changed.exr");
  EXPECT_EQ(differs.exitCode, 5) << differs.output;
  EXPECT_NE(differs.output.find("\"linear_max_diff\":0.25"), std::string::npos) << differs.output;
  // A NaN or an infinity against a finite value differs without bound: "inf" in the text,
  // null in the JSON (which has no infinity or NaN); the same NaN in both, by nothing.
  for (float odd : {std::nanf(""), HUGE_VALF}) {
    RadianceImage bad = readFloatImage(r.dir + "/render.pfm");
    bad.pixel(1, 1)[0] = odd;
    writeImageAtomic(bad, r.dir + "/odd.pfm", 2.2);
    RunResult text = runVkrt("diff " + r.dir + "/render.pfm " + r.dir + "/odd.pfm");
    EXPECT_NE(text.output.find("linear      max diff inf, RMSE inf"), std::string::npos) << text.output;
    RunResult json = runVkrt("diff --json " + r.dir + "/render.pfm " + r.dir + "/odd.pfm");
    EXPECT_NE(json.output.find("\"linear_max_diff\":null,\"linear_rmse\":null"), std::string::npos) << json.output;
    EXPECT_EQ(json.output.find("nan"), std::string::npos) << json.output;
    EXPECT_EQ(json.output.find("inf"), std::string::npos) << json.output;
    RunResult self = runVkrt("diff --json " + r.dir + "/odd.pfm " + r.dir + "/odd.pfm");
    EXPECT_NE(self.output.find("\"linear_max_diff\":0,\"linear_rmse\":0"), std::string::npos) << self.output;
  }
  RunResult check = runVkrt("--backend cpu --seed 5 -o " + r.dir + "/checked.png --check " + r.dir + "/render.exr " +
                            r.dir + "/s.test");
  EXPECT_EQ(check.exitCode, 0) << check.output;
  EXPECT_NE(check.output.find("PASS"), std::string::npos) << check.output;
}

TEST(CliConvert, RefusesWhatItMustNotWrite) {
  Renders r = renderAll("refusals");
  const std::string before = readFile(r.dir + "/render.exr");
  RunResult self = runVkrt("convert " + r.dir + "/render.exr " + r.dir + "/render.exr");
  EXPECT_EQ(self.exitCode, 1) << self.output;
  EXPECT_EQ(readFile(r.dir + "/render.exr"), before);
  RunResult unnamed = runVkrt("convert " + r.dir + "/render.exr " + r.dir + "/out.jpg");
  EXPECT_EQ(unnamed.exitCode, 1) << unnamed.output;
  EXPECT_NE(unnamed.output.find("is not named .png, .ppm, .pfm or .exr"), std::string::npos) << unnamed.output;
  EXPECT_FALSE(fileExists(r.dir + "/out.jpg"));
  RunResult one = runVkrt("convert " + r.dir + "/render.exr");
  EXPECT_NE(one.output.find("convert needs two images"), std::string::npos) << one.output;
  RunResult typo = runVkrt("convrt " + r.dir + "/render.exr " + r.dir + "/x.png");
  EXPECT_NE(typo.output.find("did you mean 'convert'?"), std::string::npos) << typo.output;
  RunResult missing = runVkrt("convert " + r.dir + "/none.exr " + r.dir + "/x.png");
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_FALSE(fileExists(r.dir + "/x.png"));
  EXPECT_EQ(fileCount(r.dir), 5u);   // the scene and its four renders: nothing else, no temporary file
}

// EXR tiles and sample batches merge as PFM ones do: the crops into the full render, the
// batches into the mean of their samples.
TEST(CliConvert, MergeTakesExrCropsAndBatches) {
  Renders r = renderAll("merge");
  const std::string d = r.dir;
  for (const char* crop : {"0,0,24,10", "0,10,24,18"}) {
    RunResult run = runVkrt("--backend cpu -q --seed 5 --crop " + std::string(crop) + " -o " + d + "/tile-" + crop +
                            ".exr " + d + "/s.test");
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  RunResult tiles = runVkrt("merge -o " + d + "/tiles.exr " + d + "/tile-0,0,24,10.exr " + d + "/tile-0,10,24,18.exr");
  ASSERT_EQ(tiles.exitCode, 0) << tiles.output;
  EXPECT_TRUE(sameBits(readFloatImage(d + "/tiles.exr"), readFloatImage(d + "/render.exr")));
  for (int seed : {5, 6}) {
    RunResult run = runVkrt("--backend cpu -q --seed " + std::to_string(seed) + " -o " + d + "/batch-" +
                            std::to_string(seed) + ".exr " + d + "/s.test");
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  RunResult batches = runVkrt("merge -o " + d + "/mean.png " + d + "/batch-5.exr " + d + "/batch-6.exr");
  ASSERT_EQ(batches.exitCode, 0) << batches.output;
  EXPECT_NE(batches.output.find("averaged 2 batches (8 samples per pixel)"), std::string::npos) << batches.output;
}
