// Messages that say what happened: a number too small for a double, a folder on the way
// that is a file, a huge token cut short, --strict's exit statuses as --help says them,
// options that write nothing refused rather than ignored, PNG under another name warned of.
#include <cstdio>
#include <filesystem>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "cli/options.h"
#include "gpu_types.h"
#include "scene/number.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene = "size 20 15\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\ndiffuse 0.5 0 0\n"
                           "sphere 0 0 0 1\n";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Runs vkrt with `args` from the folder `dir`.
RunResult runIn(const std::string& dir, const std::string& args) {
  return runCommand("cd '" + dir + "' && '" + vkrtBinary() + "' " + args);
}

}  // namespace

// Below the smallest positive double a number is "too small", not "not finite"; the
// subnormal range is accepted; above the largest, "not finite" (it would be infinite).
TEST(Messages, ANumberTooSmallForADoubleSaysSo) {
  double v = 1;
  for (const char* s : {"1e-400", "-1e-400", "+1e-400", "0.001e-322", "2.4e-324", "1e-99999999999999999999"})
    EXPECT_EQ(parseNumber(s, v), NumberStatus::TooSmall) << s;
  for (const char* s : {"1e400", "-1e400", "1000e306", "1e99999999999999999999"})
    EXPECT_EQ(parseNumber(s, v), NumberStatus::NotFinite) << s;
  EXPECT_EQ(parseNumber("1e-310", v), NumberStatus::Ok);
  EXPECT_EQ(v, 1e-310);
  EXPECT_EQ(parseNumber("0e-400", v), NumberStatus::Ok);
  EXPECT_EQ(v, 0.0);
  std::string dir = freshDir("messages/too-small");
  writeFile(dir + "/s.test", kScene + "sphere 0 0 0 1e-400\n");
  RunResult r = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "s.test:6: error: 'sphere' argument 4: '1e-400' is too small")) << r.output;
  EXPECT_FALSE(contains(r.output, "finite")) << r.output;
}

// -o FILE/x.png where FILE is a file: that FILE is a file, not that a folder is missing.
TEST(Messages, AFileOnTheOutputsWayIsNamed) {
  std::string dir = freshDir("messages/file-as-folder");
  writeFile(dir + "/s.test", kScene);
  writeFile(dir + "/file", "x");
  RunResult direct = runVkrt("--backend cpu -o " + dir + "/file/x.png " + dir + "/s.test");
  EXPECT_EQ(direct.exitCode, 4) << direct.output;
  EXPECT_TRUE(contains(direct.output, "output directory '" + dir + "/file' is not a directory: it is a regular file"))
      << direct.output;
  RunResult deeper = runVkrt("--backend cpu -o " + dir + "/file/sub/x.png " + dir + "/s.test");
  EXPECT_EQ(deeper.exitCode, 4) << deeper.output;
  EXPECT_TRUE(contains(deeper.output, "'" + dir + "/file' is a regular file, not a directory")) << deeper.output;
  EXPECT_FALSE(contains(direct.output + deeper.output, "does not exist"));
}

// A huge token is echoed cut short, with its length: in a scene (a 500 kB unknown command),
// on the command line (a 100 kB value); a 10 MB one is a line past the limit, not echoed.
TEST(Messages, HugeTokensAreCutShort) {
  std::string dir = freshDir("messages/huge-token");
  writeFile(dir + "/warn.test", kScene + std::string(500000, 'q') + " 1 2 3\n");
  RunResult warned = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/warn.test");
  EXPECT_EQ(warned.exitCode, 0) << warned.output.substr(0, 1000);
  EXPECT_TRUE(contains(warned.output, "unknown command '" + std::string(200, 'q') + "... (500000 bytes)'"))
      << warned.output.substr(0, 1000);
  EXPECT_LT(warned.output.size(), 2000u) << warned.output.substr(0, 1000);
  writeFile(dir + "/huge.test", kScene + std::string(10000000, 'q') + "\n");
  RunResult huge = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/huge.test");
  EXPECT_EQ(huge.exitCode, 2) << huge.output.substr(0, 1000);
  EXPECT_LT(huge.output.size(), 2000u) << huge.output.substr(0, 1000);
  const std::size_t usage = std::string(usageText()).size();
  for (const char* option : {"--size", "--backend", "--max-pixels-over"}) {
    RunResult r = runVkrt(std::string(option) + " " + std::string(100000, '7') + " " + dir + "/warn.test");
    EXPECT_EQ(r.exitCode, 1) << option;
    EXPECT_TRUE(contains(r.output, "... (100000 bytes)")) << option << r.output.substr(0, 1000);
    EXPECT_LT(r.output.size(), usage + 1000) << option;
  }
}

// --strict turns the command line's warnings into usage errors (1) and the scene's into
// scene errors (2), as --help says.
TEST(Messages, StrictExitStatusesAreTheOnesHelpGives) {
  std::string dir = freshDir("messages/strict");
  writeFile(dir + "/s.test", kScene);
  RunResult spp = runVkrt("--strict --spp 4 --backend cpu -o " + dir + "/o.png " + dir + "/s.test");
  EXPECT_EQ(spp.exitCode, 1) << spp.output;
  writeFile(dir + "/warn.test", kScene + "unknowncommand 1\n");
  RunResult scene = runVkrt("--strict --backend cpu -o " + dir + "/o.png " + dir + "/warn.test");
  EXPECT_EQ(scene.exitCode, 2) << scene.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
  RunResult help = runVkrt("--help");
  EXPECT_TRUE(contains(help.output, "and the command line's (exit 1: --spp for a Whitted scene")) << help.output;
  EXPECT_TRUE(contains(help.output, "1    usage error: the command line (with --strict: its warnings too)"))
      << help.output;
}

// Options that would write nothing, or somewhere else than asked, are usage errors:
// --compare with -o (--compare writes no image), '-' as an output (standard output).
TEST(Messages, OutputsThatWouldNotBeWrittenAreRefused) {
  std::string dir = freshDir("messages/refused-outputs");
  writeFile(dir + "/s.test", kScene);
  RunResult compare = runIn(dir, "--compare -o x.png s.test");
  EXPECT_EQ(compare.exitCode, 1) << compare.output;
  EXPECT_TRUE(contains(compare.output, "--compare writes no image")) << compare.output;
  RunResult compareDir = runIn(dir, "--compare -o out/ s.test");
  EXPECT_EQ(compareDir.exitCode, 1) << compareDir.output;
  for (const char* args : {"--backend cpu -o - s.test", "--backend cpu --output=- s.test", "merge -o - a.png",
                           "diff a.png b.png --diff -", "--backend cpu s.test --check a.png --diff -"}) {
    RunResult r = runIn(dir, args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, "vkrt writes images into files, not to standard output")) << r.output;
  }
  RunResult dotSlash = runIn(dir, "-q --backend cpu -o ./- s.test");   // a file named '-', asked for so
  EXPECT_EQ(dotSlash.exitCode, 0) << dotSlash.output;
  EXPECT_TRUE(fileExists(dir + "/-"));
  fs::remove(dir + "/-");
  EXPECT_FALSE(fileExists(dir + "/x.png"));
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// merge -o x.bmp says that it writes PNG under that name, as a render does; --diff x.pfm
// (a float heatmap) is refused, --diff x.ppm writes PPM.
TEST(Messages, AnImageUnderAnotherNameIsWarnedOf) {
  std::string dir = freshDir("messages/names");
  writeFile(dir + "/s.test", kScene);
  ASSERT_EQ(runIn(dir, "-q --backend cpu --crop 0,0,20,15 -o t.png s.test").exitCode, 0);
  RunResult merge = runIn(dir, "merge -o x.bmp t.png");
  EXPECT_EQ(merge.exitCode, 0) << merge.output;
  EXPECT_TRUE(contains(merge.output, "vkrt: warning: output file 'x.bmp' is not named .png, .ppm, .pfm or .exr: vkrt "
                                     "writes PNG, under that name"))
      << merge.output;
  ASSERT_EQ(runIn(dir, "-q --backend cpu -o a.png s.test").exitCode, 0);
  RunResult pfm = runIn(dir, "diff a.png t.png --diff h.pfm");
  EXPECT_EQ(pfm.exitCode, 1) << pfm.output;
  RunResult ppm = runIn(dir, "diff a.png t.png --diff h.ppm");
  EXPECT_EQ(ppm.exitCode, 0) << ppm.output;
  EXPECT_EQ(readFile(dir + "/h.ppm").rfind("P6\n", 0), 0u);
  RunResult other = runIn(dir, "diff a.png t.png --diff h.img");
  EXPECT_TRUE(contains(other.output, "heatmap file 'h.img' is not named .png or .ppm")) << other.output;
}

// The path shader draws at most kRngBounceStride - kRngSlotLightBase random numbers for a
// vertex's light samples (gpu_types.h); a scene that needs more is refused by the Vulkan
// backend at its `lightsamples` line, before anything is written, with the limit and the way
// out; one sample fewer renders, and so does the CPU backend.
TEST(Messages, TooManyLightSamplesForTheVulkanBackendNameTheirLine) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("messages/light-samples");
  const int most = static_cast<int>(gpu::kRngBounceStride - gpu::kRngSlotLightBase) / 2;   // one quad light
  auto scene = [](int samples) {
    return "size 8 6\nintegrator direct\ncamera 0 1 3 0 0 0 0 1 0 45\nlightsamples " + std::to_string(samples) +
           "\nquadLight -0.5 2 -0.5 1 0 0 0 0 1 5 5 5\nvertex -2 0 -2\nvertex 2 0 -2\nvertex 2 0 2\n"
           "diffuse 0.5 0.5 0.5\ntri 0 1 2\n";
  };
  writeFile(dir + "/over.test", scene(most + 1));
  RunResult over = runIn(dir, "-o over.png over.test");
  EXPECT_EQ(over.exitCode, 2) << over.output;
  EXPECT_TRUE(contains(over.output, "over.test:4: error: the Vulkan backend draws at most " +
                                        std::to_string(2 * most) + " random numbers")) << over.output;
  EXPECT_TRUE(contains(over.output, "(1 quad light x " + std::to_string(most + 1) + " lightsamples x 2)")) << over.output;
  EXPECT_TRUE(contains(over.output, "or --backend cpu")) << over.output;
  EXPECT_FALSE(fs::exists(dir + "/over.png"));
  writeFile(dir + "/most.test", scene(most));
  RunResult fits = runIn(dir, "-q -o most.png most.test");
  EXPECT_EQ(fits.exitCode, 0) << fits.output;
  EXPECT_TRUE(fs::exists(dir + "/most.png"));
  // --dry-run says what the render would: the same error and status, nothing written.
  RunResult dry = runIn(dir, "--dry-run -o over.png over.test");
  EXPECT_EQ(dry.exitCode, 2) << dry.output;
  EXPECT_TRUE(contains(dry.output, "over.test:4: error: the Vulkan backend draws at most")) << dry.output;
  // Only light samples that are drawn count: none under pathtracer without next-event
  // estimation; the emitting surfaces' only under pathtracer with it (not under direct).
  std::string text = scene(most + 1);
  text.replace(text.find("integrator direct"), 17, "integrator pathtracer\nnexteventestimation off\nmaxdepth 1");
  writeFile(dir + "/off.test", text + "emission 1 1 1\nsphere 0 3 0 0.2\n");
  RunResult off = runIn(dir, "-q -o off.png off.test");
  EXPECT_EQ(off.exitCode, 0) << off.output;
  writeFile(dir + "/direct.test", scene(most) + "emission 1 1 1\nsphere 0 3 0 0.2\n");
  RunResult direct = runIn(dir, "-q -o direct.png direct.test");
  EXPECT_EQ(direct.exitCode, 0) << direct.output;
  // 1 quad light x 13107 x 2 and 13107 x 3 for the emitting sphere: 65535, over the limit.
  writeFile(dir + "/nee.test", "size 8 6\nintegrator pathtracer\nnexteventestimation on\nmaxdepth 1\n"
                               "lightsamples 13107\ncamera 0 1 3 0 0 0 0 1 0 45\n"
                               "quadLight -0.5 2 -0.5 1 0 0 0 0 1 5 5 5\nemission 1 1 1\nsphere 0 3 0 0.2\n");
  RunResult nee = runIn(dir, "--dry-run -o nee.png nee.test");
  EXPECT_EQ(nee.exitCode, 2) << nee.output;
  EXPECT_TRUE(contains(nee.output, "nee.test:5: error:")) << nee.output;
  EXPECT_TRUE(contains(nee.output, "(1 quad light x 13107 lightsamples x 2, and 13107 lightsamples x 3 for the "
                                   "emitting surfaces)")) << nee.output;
}

// --compare writes nothing, but says, for each backend, how many pixels were NaN or infinite
// (two quad lights at the largest float over a white sphere), as a render would.
TEST(Messages, CompareWarnsOfNonFinitePixels) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("messages/compare-non-finite");
  writeFile(dir + "/nf.test", "size 8 8\nintegrator pathtracer\nspp 2\nnexteventestimation on\n"
                              "camera 0 0 4 0 0 0 0 1 0 40\nquadLight -3 1.01 -3 0 0 6 6 0 0 3e38 3e38 3e38\n"
                              "quadLight -3 1.02 -3 0 0 6 6 0 0 3e38 3e38 3e38\ndiffuse 1 1 1\nsphere 0 0 0 1\n");
  RunResult r = runIn(dir, "--compare nf.test");
  EXPECT_TRUE(contains(r.output, "vkrt: warning: vulkan: ")) << r.output;
  EXPECT_TRUE(contains(r.output, "vkrt: warning: cpu: ")) << r.output;
  EXPECT_TRUE(contains(r.output, "a NaN or infinite colour (compared as 8-bit: NaN as 0, +infinity as 255)")) << r.output;
}

// The warning names the backend whose pixels were not finite, and not the other: two scenes
// where only one backend goes beyond float32. On a triangle lit head-on, ambient + emission
// (3e38 each) less a light of -3e38 is 3e38 in the CPU's doubles, while Vulkan's floats
// overflow on the first sum. A light of 3e38 over an attenuation divisor of 0.5 is 6e38 in
// the CPU's doubles, while Vulkan keeps the light over its divisor finite (shaders/lights.glsl)
// and writes the largest float.
TEST(Messages, CompareNamesOnlyTheBackendWhosePixelsWereNotFinite) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("messages/compare-one-backend-non-finite");
  const std::string triangle = "size 8 8\ncamera 0 0 4 0 0 0 0 1 0 30\ndiffuse 1 1 1\nmaxverts 3\n"
                               "vertex -1 -1 0\nvertex 1 -1 0\nvertex 0 1 0\ntri 0 1 2\n";
  const struct {
    const char* lighting;
    const char* named;
    const char* notNamed;
  } cases[] = {
      {"ambient 3e38 3e38 3e38\nemission 3e38 3e38 3e38\ndirectional 0 0 1 -3e38 -3e38 -3e38\n", "vulkan", "cpu"},
      {"attenuation 0.5 0 0\npoint 0 0 1000 3e38 3e38 3e38\n", "cpu", "vulkan"}};
  for (const auto& c : cases) {
    writeFile(dir + "/s.test", std::string(c.lighting) + triangle);
    RunResult r = runIn(dir, "--compare s.test");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, std::string("vkrt: warning: ") + c.named + ": ")) << c.lighting << r.output;
    EXPECT_FALSE(contains(r.output, std::string("vkrt: warning: ") + c.notNamed + ": ")) << c.lighting << r.output;
  }
}
