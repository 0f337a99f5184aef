// --size and --scale: the scene's picture sampled at another resolution. A scaled render must
// be the very image of the same scene text with its `size` line changed, on both backends.
#include <gtest/gtest.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// `text` with its (first) `size` line replaced by "size W H". (No std::regex: GCC 12 warns
// inside it under the sanitizers.)
std::string withSize(const std::string& text, int w, int h) {
  std::size_t at = text.rfind("size ", 0) == 0 ? 0 : text.find("\nsize ");
  EXPECT_NE(at, std::string::npos) << "no size line";
  if (at == std::string::npos) return text;
  if (at > 0) ++at;   // past the newline
  std::size_t end = text.find('\n', at);
  return text.substr(0, at) + "size " + std::to_string(w) + " " + std::to_string(h) +
         (end == std::string::npos ? std::string() : text.substr(end));
}

// Renders `scene` with `options` and the same text resized to w x h without them; both images
// must be equal byte for byte, and w x h.
void expectSameAsResizedText(const std::string& name, const std::string& backend, const std::string& options,
                             int w, int h) {
  std::string dir = freshDir("cli-preview/" + name + "-" + backend);
  std::string text = readFile(sourcePath("scenes/" + name + ".test"));
  writeFile(dir + "/scene.test", text);
  writeFile(dir + "/resized.test", withSize(text, w, h));
  RunResult a = runVkrt("--backend " + backend + " " + options + " -o " + dir + "/scaled.png " + dir + "/scene.test");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  EXPECT_NE(a.output.find("(" + std::to_string(w) + "x" + std::to_string(h) + ")"), std::string::npos) << a.output;
  RunResult b = runVkrt("--backend " + backend + " -o " + dir + "/resized.png " + dir + "/resized.test");
  ASSERT_EQ(b.exitCode, 0) << b.output;
  Image scaled = readImage(dir + "/scaled.png"), resized = readImage(dir + "/resized.png");
  EXPECT_EQ(scaled.width, w);
  EXPECT_EQ(scaled.height, h);
  EXPECT_TRUE(scaled.rgb == resized.rgb) << name << " " << backend << " " << options << ": "
                                         << imagesClose(name, scaled, resized, 0, 0).message();
}

}  // namespace

TEST(CliPreview, ScaleHalfIsTheSceneWithItsSizeHalvedOnTheCpu) {
  expectSameAsResizedText("showcase", "cpu", "--scale 0.5", 400, 250);
  expectSameAsResizedText("non_square", "cpu", "--scale=0.5", 48, 16);
}

TEST(CliPreview, ScaleHalfIsTheSceneWithItsSizeHalvedOnVulkan) {
  VKRT_REQUIRE_GPU(ctx);
  expectSameAsResizedText("showcase", "vulkan", "--scale 0.5", 400, 250);
  expectSameAsResizedText("non_square", "vulkan", "--scale 0.5", 48, 16);
}

// Rounded to the nearest pixel, at least 1x1; --size sets both sides (the aspect may change:
// fovy is kept, as a scene's own `size` line would have it).
TEST(CliPreview, ScaleRoundsAndSizeSetsBothSides) {
  expectSameAsResizedText("spheres", "cpu", "--scale 0.3", 19, 14);     // 19.2 x 14.4
  expectSameAsResizedText("spheres", "cpu", "--scale 1.5", 96, 72);
  expectSameAsResizedText("spheres", "cpu", "--scale 0.0001", 1, 1);
  expectSameAsResizedText("spheres", "cpu", "--size 33x20", 33, 20);
}

TEST(CliPreview, BadValuesAreUsageErrors) {
  std::string scene = sourcePath("scenes/spheres.test");
  for (const char* bad : {"--scale 0", "--scale -1", "--scale abc", "--scale nan", "--scale inf", "--scale 0.5x",
                          "--scale", "--size 10", "--size 0x10", "--size 10x", "--size x10", "--size 16385x10",
                          "--size -3x4", "--size 10x10 --scale 2"}) {
    RunResult r = runVkrt(std::string(bad) + " -o never.png " + scene);
    EXPECT_EQ(r.exitCode, 1) << bad << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("vkrt: error: ", 0), 0u) << r.output;
    EXPECT_FALSE(fileExists("never.png"));
  }
  RunResult size = runVkrt("--size 10 " + scene);
  EXPECT_NE(size.output.find("--size expects WIDTHxHEIGHT, each from 1 to 16384 (e.g. 320x240), got '10'"),
            std::string::npos)
      << size.output;
  RunResult scale = runVkrt("--scale -1 " + scene);
  EXPECT_NE(scale.output.find("--scale expects a number greater than 0 (e.g. 0.5), got '-1'"), std::string::npos)
      << scale.output;
  // Beyond the largest image: found once the scene's size is known, still the command line's.
  RunResult big = runVkrt("--backend cpu --scale 1000 -o never.png " + scene);
  EXPECT_EQ(big.exitCode, 1) << big.output;
  EXPECT_NE(big.output.find("--scale 1000 makes " + scene + "'s 64x48 image 64000x48000, larger than 16384 on a side"),
            std::string::npos)
      << big.output;
  EXPECT_FALSE(fileExists("never.png"));
}
