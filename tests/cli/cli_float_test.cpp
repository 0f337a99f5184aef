// The command line of float output and sample batches: --spp, --seed and --time (validation,
// and the warning for a Whitted scene), -o NAME.pfm, `vkrt merge` of sample batches, and of PFM crops.
#include <gtest/gtest.h>

#include "cpu/reference.h"
#include "image/encode.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/render_identity.h"
#include "image/samples.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const char* kScene = "size 16 12\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 2 2 2 1 1 1\nambient 0.1 0.05 0.05\n"
                     "diffuse 0.6 0.3 0.2\nsphere 0 0 0 1\n";

}  // namespace

TEST(CliFloat, SampleOptionsAreValidated) {
  const std::pair<const char*, const char*> cases[] = {
      {"--spp 0 x.test", "--spp expects an integer from 1 to 1073741824, got '0'"},
      {"--spp many x.test", "--spp expects an integer from 1 to 1073741824, got 'many'"},
      {"--seed -1 x.test", "--seed expects a whole number from 0 to 4294967295, got '-1'"},
      {"--seed 4294967296 x.test", "--seed expects a whole number from 0 to 4294967295, got '4294967296'"},
      {"--time 0 x.test", "--time expects seconds, a number greater than 0 and at most a year, 31536000 (e.g. 2.5), got '0'"},
      {"--time nan x.test", "--time expects seconds, a number greater than 0 and at most a year, 31536000 (e.g. 2.5), got 'nan'"},
      {"--time=-3 x.test", "--time expects seconds, a number greater than 0 and at most a year, 31536000 (e.g. 2.5), got '-3'"},
      {"--time 1e8 x.test", "at most a year, 31536000 (e.g. 2.5), got '1e8'"},
      {"--time", "option --time needs a value"},
  };
  for (const auto& [args, message] : cases) {
    RunResult r = runVkrt(args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
  RunResult help = runVkrt("--help");
  for (const char* option : {"--spp N", "--seed N", "--time SECONDS", ".pfm", "vkrt merge -o OUT.pfm|OUT.png BATCH.pfm"})
    EXPECT_NE(help.output.find(option), std::string::npos) << option;
}

// The Whitted model has one deterministic sample: the options change nothing and say so.
TEST(CliFloat, SampleOptionsOnAWhittedSceneWarnAndChangeNothing) {
  std::string dir = freshDir("cli-float/whitted");
  writeFile(dir + "/s.test", kScene);
  RunResult plain = runVkrt("--backend cpu -o " + dir + "/plain.png " + dir + "/s.test");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_EQ(plain.output.find("warning:"), std::string::npos) << plain.output;
  RunResult r = runVkrt("--backend cpu --spp 8 --seed 3 --time 5 -o " + dir + "/o.png " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: warning: --spp, --seed and --time do not apply to " + dir +
                          "/s.test: its integrator is raytracer (one deterministic sample per pixel)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(readImage(dir + "/o.png").rgb, readImage(dir + "/plain.png").rgb);
  RunResult one = runVkrt("--backend cpu --spp 8 -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_NE(one.output.find("vkrt: warning: --spp does not apply to"), std::string::npos) << one.output;
  RunResult quiet = runVkrt("--backend cpu -q --spp 8 -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(quiet.output, "");
  RunResult strict = runVkrt("--backend cpu --strict --time 2 -o " + dir + "/strict.png " + dir + "/s.test");
  EXPECT_EQ(strict.exitCode, 1) << strict.output;
  EXPECT_NE(strict.output.find("--time does not apply to"), std::string::npos) << strict.output;
  EXPECT_FALSE(fileExists(dir + "/strict.png"));
  RunResult strata = runVkrt("--backend cpu --strict --sampler stratified -o " + dir + "/strata.png " + dir + "/s.test");
  EXPECT_EQ(strata.exitCode, 1) << strata.output;
  EXPECT_NE(strata.output.find("--sampler stratified does not apply to"), std::string::npos) << strata.output;
  EXPECT_FALSE(fileExists(dir + "/strata.png"));
}

// -o NAME.pfm: the renderer's floats as they are; the PNG of the same render is their encoding.
TEST(CliFloat, PfmOutputIsTheRenderersRadiance) {
  std::string dir = freshDir("cli-float/pfm");
  writeFile(dir + "/s.test", kScene);
  SceneDesc scene = parseScene(kScene, dir + "/s.test");
  RadianceImage expected = renderReference(scene, buildBvh(scene), CpuOptions{}, nullptr);
  for (const char* backend : {"cpu", "vulkan"}) {
    if (std::string(backend) == "vulkan" && !gpuContextOrSkip()) return;
    std::string out = dir + "/" + backend;
    RunResult r = runVkrt(std::string("--backend ") + backend + " -o " + out + ".pfm " + dir + "/s.test");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("vkrt: wrote " + out + ".pfm (16x12) in"), std::string::npos) << r.output;
    RunResult png = runVkrt(std::string("--backend ") + backend + " -o " + out + ".png " + dir + "/s.test");
    ASSERT_EQ(png.exitCode, 0) << png.output;
    RadianceImage pfm = readPfm(out + ".pfm");
    EXPECT_TRUE(pfm.text.empty());   // a Whitted render is exact: no samples record
    EXPECT_EQ(readImage(out + ".png").rgb, encodeImage(pfm, 1.0).rgb) << backend;
    if (std::string(backend) == "cpu") {
      EXPECT_EQ(pfm.rgb, expected.rgb);
    } else {
      EXPECT_TRUE(imagesClose("cli-float-pfm", encodeImage(pfm, 1.0), encodeImage(expected, 1.0), 1, 2));
    }
  }
}

// Batches written as a farm's jobs would write them, averaged into PFM (exact) and PNG (the
// recorded gamma); refusals are usage errors (1).
TEST(CliFloat, MergeAveragesSampleBatches) {
  std::string dir = freshDir("cli-float/merge");
  RadianceImage a(5, 4), b(5, 4);
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    a.rgb[i] = 0.01f * static_cast<float>(i);
    b.rgb[i] = 0.5f;
  }
  a.text.emplace_back(kSamplesKeyword, formatSampleRecord({{{1, 0, 1}}, 2.0}));
  b.text.emplace_back(kSamplesKeyword, formatSampleRecord({{{2, 0, 3}}, 2.0}));
  writePfmAtomic(a, dir + "/a.pfm");
  writePfmAtomic(b, dir + "/b.pfm");
  RunResult r = runVkrt("merge -o " + dir + "/mean.pfm " + dir + "/a.pfm " + dir + "/b.pfm");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: averaged 2 batches (4 samples per pixel) into " + dir + "/mean.pfm (5x4)"),
            std::string::npos)
      << r.output;
  RadianceImage mean = readPfm(dir + "/mean.pfm");
  for (std::size_t i = 0; i < mean.rgb.size(); ++i)
    EXPECT_FLOAT_EQ(mean.rgb[i], (a.rgb[i] + 3 * b.rgb[i]) / 4) << i;
  ASSERT_EQ(mean.text.size(), 1u);
  EXPECT_EQ(mean.text[0].second, "4 gamma 2 seeds 1:0+1 2:0+3");
  RunResult png = runVkrt("merge -q -o " + dir + "/mean.png " + dir + "/a.pfm " + dir + "/b.pfm");
  ASSERT_EQ(png.exitCode, 0) << png.output;
  EXPECT_EQ(png.output, "");
  EXPECT_EQ(readImage(dir + "/mean.png").rgb, encodeImage(mean, 2.0).rgb);
  RunResult same = runVkrt("merge -o " + dir + "/x.pfm " + dir + "/a.pfm " + dir + "/a.pfm");
  EXPECT_EQ(same.exitCode, 1) << same.output;
  EXPECT_NE(same.output.find("hold the same samples (seed 1, sample 0)"), std::string::npos) << same.output;
  EXPECT_FALSE(fileExists(dir + "/x.pfm"));
}

// A scene's `output NAME.pfm` is a name vkrt writes as named: no warning, a PFM.
TEST(CliFloat, SceneOutputPfmIsWrittenAsPfmWithoutAWarning) {
  std::string dir = freshDir("cli-float/scene-output");
  writeFile(dir + "/s.test", std::string(kScene) + "output " + dir + "/o.pfm\n");
  RunResult r = runVkrt("--backend cpu --strict " + dir + "/s.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning:"), std::string::npos) << r.output;
  EXPECT_TRUE(isPfmFile(dir + "/o.pfm"));
}

// The flow of a render farm through the command line, for a path integrator's scene: --spp
// and --seed recorded in each batch, --time reported, the batches merged with the scene's
// gamma. (The images' values are the integrators' business; this checks the plumbing.)
TEST(CliFloat, PathSceneBatchesCarryTheirSamplesAndMerge) {
  std::string dir = freshDir("cli-float/path");
  writeFile(dir + "/p.test",
            "size 8 6\nintegrator analyticdirect\nspp 2\ngamma 2.2\ncamera 0 0 4 0 0 0 0 1 0 45\n"
            "quadLight -1 2 -1 2 0 0 0 0 2 1 1 1\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n");
  RunResult a = runVkrt("--backend cpu --spp 4 --seed 3 -o " + dir + "/a.pfm " + dir + "/p.test");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  EXPECT_NE(a.output.find("(8x6, 4 samples per pixel)"), std::string::npos) << a.output;
  EXPECT_EQ(a.output.find("warning:"), std::string::npos) << a.output;
  RunResult b = runVkrt("--backend cpu --seed 4 -o " + dir + "/b.pfm " + dir + "/p.test");   // the scene's spp 2
  ASSERT_EQ(b.exitCode, 0) << b.output;
  const auto aText = readPfm(dir + "/a.pfm").text;
  ASSERT_EQ(aText.size(), 2u);
  EXPECT_EQ(aText[0], (std::pair<std::string, std::string>{kSamplesKeyword, "4 gamma 2.2000000000000002 seeds 3:0+4"}));
  EXPECT_EQ(aText[1].first, kRenderKeyword);   // the same render as b.pfm's: the seed and spp are not in it
  EXPECT_EQ(readPfm(dir + "/b.pfm").text[1], aText[1]);
  RunResult m = runVkrt("merge -o " + dir + "/m.png " + dir + "/a.pfm " + dir + "/b.pfm");
  ASSERT_EQ(m.exitCode, 0) << m.output;
  EXPECT_NE(m.output.find("averaged 2 batches (6 samples per pixel)"), std::string::npos) << m.output;
  RunResult mf = runVkrt("merge -q -o " + dir + "/m.pfm " + dir + "/a.pfm " + dir + "/b.pfm");
  ASSERT_EQ(mf.exitCode, 0) << mf.output;
  EXPECT_EQ(readImage(dir + "/m.png").rgb, encodeImage(readPfm(dir + "/m.pfm"), 2.2).rgb);
  RunResult t = runVkrt("--backend cpu --time 0.2 -o " + dir + "/t.png " + dir + "/p.test");
  ASSERT_EQ(t.exitCode, 0) << t.output;
  EXPECT_NE(t.output.find("samples per pixel when the time was up"), std::string::npos) << t.output;
}

// Crops written as PFM (linear float, as rendered) merge like 8-bit ones: a grid of crops of
// a path-traced render with one seed is the full render bit for bit, carries its samples
// record, and encodes to PNG with the recorded gamma. Whitted PFM crops (no samples record)
// merge too. Tiles of two kinds, or of renders with other samples, are refused.
TEST(CliFloat, MergeOfPfmCropsIsTheFullRender) {
  std::string dir = freshDir("cli-float/pfm-crops");
  writeFile(dir + "/p.test",
            "size 13 9\nintegrator pathtracer\nspp 3\ngamma 2.2\nnexteventestimation on\nmaxdepth 3\n"
            "camera 0 0 4 0 0 0 0 1 0 45\nquadLight -1 2 -1 2 0 0 0 0 2 4 4 4\n"
            "diffuse 0.5 0.4 0.3\nsphere 0 0 0 1\nvertex -3 -1 -3\nvertex 3 -1 -3\nvertex 0 -1 3\ntri 0 2 1\n");
  writeFile(dir + "/w.test", kScene);
  const std::string common = "--backend cpu -q --seed 5 ";
  for (const char* scene : {"p", "w"}) {
    const std::string s = dir + "/" + scene;
    RunResult full = runVkrt(common + "-o " + s + "-full.pfm " + s + ".test");
    ASSERT_EQ(full.exitCode, 0) << full.output;
    RadianceImage reference = readPfm(s + "-full.pfm");
    const int w = reference.width, h = reference.height;
    const int xs[] = {0, 5, w}, ys[] = {0, 4, h};
    std::string tiles;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        std::string tile = s + "-tile" + std::to_string(j * 2 + i) + ".pfm";
        RunResult t = runVkrt(common + "--crop " + std::to_string(xs[i]) + "," + std::to_string(ys[j]) + "," +
                              std::to_string(xs[i + 1]) + "," + std::to_string(ys[j + 1]) + " -o " + tile + " " + s +
                              ".test");
        ASSERT_EQ(t.exitCode, 0) << t.output;
        tiles = " " + tile + tiles;
      }
    RunResult m = runVkrt("merge -o " + s + "-merged.pfm" + tiles);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    EXPECT_NE(m.output.find("merged 4 tiles into " + s + "-merged.pfm (" + std::to_string(w) + "x" + std::to_string(h)),
              std::string::npos)
        << m.output;
    RadianceImage merged = readPfm(s + "-merged.pfm");
    ASSERT_EQ(merged.width, w);
    EXPECT_TRUE(merged.rgb == reference.rgb) << scene << ": the merged crops differ from the full render";
    EXPECT_EQ(merged.text, reference.text) << scene;   // the samples record (path), or none (Whitted)
    RunResult png = runVkrt("merge -q -o " + s + "-merged.png" + tiles);
    ASSERT_EQ(png.exitCode, 0) << png.output;
    EXPECT_EQ(readImage(s + "-merged.png").rgb, encodeImage(reference, scene == std::string("p") ? 2.2 : 1.0).rgb)
        << scene;
  }
  // Refusals, with nothing written.
  RunResult other = runVkrt("--backend cpu -q --seed 6 --crop 5,0,13,4 -o " + dir + "/p-seed6.pfm " + dir + "/p.test");
  ASSERT_EQ(other.exitCode, 0) << other.output;
  RunResult png = runVkrt("--backend cpu -q --seed 5 --crop 5,0,13,4 -o " + dir + "/p-tile.png " + dir + "/p.test");
  ASSERT_EQ(png.exitCode, 0) << png.output;
  const std::pair<std::string, std::string> refused[] = {
      {dir + "/p-tile0.pfm " + dir + "/p-seed6.pfm " + dir + "/p-tile2.pfm " + dir + "/p-tile3.pfm",
       "tiles of different renders: '" + dir + "/p-tile0.pfm' holds the samples 3 gamma 2.2000000000000002 seeds 5:0+3, '" +
           dir + "/p-seed6.pfm' the samples 3 gamma 2.2000000000000002 seeds 6:0+3"},
      {dir + "/p-tile0.pfm " + dir + "/p-tile.png", "tile '" + dir + "/p-tile0.pfm' is a PFM file: merge tiles of one kind"},
  };
  for (const auto& [tiles, message] : refused) {
    RunResult r = runVkrt("merge -o " + dir + "/never.pfm " + tiles);
    EXPECT_EQ(r.exitCode, 1) << tiles << "\n" << r.output;
    EXPECT_NE(r.output.find("vkrt: error: " + message), std::string::npos) << tiles << "\n" << r.output;
    EXPECT_FALSE(fileExists(dir + "/never.pfm"));
  }
}
