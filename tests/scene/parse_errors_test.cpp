// Every kind of bad input of doc/scene-format.md, "Warnings and errors": the parser's located message, and through the
// CLI: exit status 2, the message on stderr, no image written, an existing image untouched.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "util/errors.h"
#include "render/render.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

struct BadInput {
  const char* name;
  std::string text;
  int line;              // expected line of the (first) diagnostic
  const char* message;   // expected part of its message
};

const std::string kOk = "size 64 48\ncamera 0 0 5 0 0 0 0 1 0 45\n";   // lines 1-2
const std::string kPath = kOk + "integrator pathtracer\n";                // lines 1-3

std::vector<BadInput> badInputs() {
  return {
      {"UnparsableNumber", kOk + "vertex 1 x 0\n", 3, "argument 2: expected a number, got 'x'"},
      {"TrailingGarbageInNumber", kOk + "vertex 1 2z 0\n", 3, "expected a number, got '2z'"},
      {"NaN", kOk + "vertex nan 0 0\n", 3, "expected a finite number, got 'nan'"},
      {"Infinity", kOk + "sphere 0 0 0 inf\n", 3, "expected a finite number, got 'inf'"},
      {"Overflow", kOk + "translate 1e999 0 0\n", 3, "expected a finite number, got '1e999'"},
      {"MissingArgument", kOk + "vertex 1 2\n", 3, "'vertex' expects 3 arguments (x y z), got 2"},
      {"MissingOutputName", kOk + "output\n", 3, "'output' expects 1 argument (a file name without spaces), got 0"},
      {"SizeAbsent", "camera 0 0 5 0 0 0 0 1 0 45\n", 1, "no 'size' command"},
      {"SizeAbsentEmptyFile", "", 1, "no 'size' command"},
      {"SizeZero", "size 0 48\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1, "expected an integer from 1 to 16384, got '0'"},
      {"SizeNegative", "size 64 -1\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1, "got '-1'"},
      {"SizeTooLarge", "size 100000 100000\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1, "from 1 to 16384, got '100000'"},
      {"SizeNotInteger", "size 64.5 48\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1, "got '64.5'"},
      {"RepeatedSizeLastInvalid", kOk + "size 64 0\n", 3, "'size' argument 2: expected an integer from 1 to 16384"},
      {"NegativeMaxDepth", kOk + "maxdepth -1\n", 3, "expected a non-negative integer, got '-1'"},
      {"NegativeMaxDepthInAnotherCase", kOk + "maxDepth -1\n", 3, "expected a non-negative integer, got '-1'"},
      {"IndexOutOfRange", kOk + "vertex 0 0 0\nvertex 1 0 0\ntri 0 1 2\n", 5,
       "'tri' index 2 out of range (2 vertices defined so far)"},
      {"NegativeIndex", kOk + "vertex 0 0 0\ntri 0 -1 0\n", 4, "'tri' index -1 out of range"},
      {"TriNormalIndexOutOfRange", kOk + "vertex 0 0 0\ntrinormal 0 0 0\n", 4,
       "'trinormal' index 0 out of range (0 vertexnormals defined so far)"},
      {"PopEmptyStack", kOk + "pushTransform\npopTransform\npopTransform\n", 5,
       "popTransform with an empty transform stack"},
      {"ZeroRotateAxis", kOk + "rotate 0 0 0 45\n", 3, "rotate axis must not be zero"},
      {"CameraFromEqualsAt", "size 64 48\ncamera 1 2 3 1 2 3 0 1 0 45\n", 2, "look-from equals look-at"},
      {"CameraUpParallel", "size 64 48\ncamera 0 0 5 0 0 0 0 0 2 45\n", 2, "up vector is parallel"},
      {"CameraUpZero", "size 64 48\ncamera 0 0 5 0 0 0 0 0 0 45\n", 2, "up vector is zero"},
      {"CameraFromAtOverflows", "size 64 48\ncamera 1e308 0 0 -1e308 0 0 0 1 0 45\n", 2,
       "look-from and look-at are too far apart: their difference overflows double precision"},
      {"CameraFovZero", "size 64 48\ncamera 0 0 5 0 0 0 0 1 0 0\n", 2, "field of view must be in (0, 180)"},
      {"CameraFov180", "size 64 48\ncamera 0 0 5 0 0 0 0 1 0 180\n", 2, "field of view must be in (0, 180)"},
      {"NegativeRadius", kOk + "sphere 0 0 0 -1\n", 3, "sphere radius must not be negative"},
      {"MissingCamera", "size 64 48\nsphere 0 0 0 1\n\n", 3, "no 'camera' command"},
      {"OutputDirectoryMissing", kOk + "output no-such-dir/x.png\n", 3,
       "output directory 'no-such-dir' does not exist"},
      {"OutputDirectoryMissingQuotedEscaped", kOk + "output caf\xC3\xA9/x.png\n", 3,
       "output directory 'caf\\xC3\\xA9' does not exist"},
      {"OutputDirectoryNotWritable", kOk + "output /proc/vkrt-test.png\n", 3,
       "output directory '/proc' is not writable"},
      {"NotText", std::string("size 64 48\ncam\0era\n", 19), 2, "file is not text (byte 0x00 in column 4)"},
      // Binary bytes of no image format (a PNG given as a scene is a usage error: suggest_test).
      {"BinaryGarbage", std::string("\x89XYZ\r\n\x1a\n\0\0\0\rIHDR", 16), 2, "file is not text (byte 0x1A in column 1)"},
      {"NegativeShininess", kOk + "shininess -2\n", 3, "shininess must not be negative"},
      {"ZeroDirectional", kOk + "directional 0 0 0 1 1 1\n", 3, "directional light direction must not be zero"},
      {"DirectionalUnderZeroScale", kOk + "scale 0 0 0\ndirectional 0 0 1 1 1 1\n", 4,
       "directional light direction vanishes under the current transform (a scale of 0)"},
      {"SingularSphere", kOk + "scale 1 0 1\nsphere 0 0 0 1\n", 4, "singular transform"},
      {"ScaleOverflows", kOk + "scale 1e200 1 1\nscale 1e200 1 1\nsphere 0 0 0 1\n", 4,
       "'scale' makes the current transform overflow"},
      {"TranslateOverflows", kOk + "translate 1e308 0 0\ntranslate 1e308 0 0\nsphere 0 0 0 1\n", 4,
       "'translate' makes the current transform overflow"},
      // doc/path-tracing.md, "Commands" (kPath: lines 1-3, integrator pathtracer)
      {"MaxDepthBelowMinusOne", kPath + "maxdepth -2\n", 4,
       "'maxdepth' argument 1: expected a non-negative integer, or -1 (no limit), got '-2'"},
      {"UnlimitedMaxDepthUnderRaytracerGivenLater", kOk + "maxdepth -1\nintegrator raytracer\n", 3,
       "got '-1': -1 (no limit) is for the path integrators, and integrator raytracer (line 4) is the Whitted model"},
      {"UnknownIntegrator", kOk + "integrator foo\n", 3,
       "'integrator' argument 1: expected raytracer, analyticdirect, direct or pathtracer, got 'foo'"},
      {"MissingIntegrator", kOk + "integrator\n", 3,
       "'integrator' expects 1 argument (raytracer, analyticdirect, direct or pathtracer), got 0"},
      {"LightSamplesZero", kPath + "lightsamples 0\n", 4,
       "'lightsamples' argument 1: expected an integer from 1 to 1000000000, got '0'"},
      {"LightSamplesNotInteger", kPath + "lightsamples 2.5\n", 4, "expected an integer from 1 to 1000000000, got '2.5'"},
      {"StratifiedLightSamplesNotSquare", kPath + "lightsamples 10\nlightstratify on\n", 5,
       "'lightstratify on' needs a perfect square 'lightsamples', got 10 (line 4)"},
      {"StratifiedThenLightSamplesNotSquare", kPath + "lightstratify on\nlightsamples 8\n", 4,
       "'lightstratify on' needs a perfect square 'lightsamples', got 8 (line 5)"},
      {"UnknownLightStratify", kPath + "lightstratify yes\n", 4, "'lightstratify' argument 1: expected on or off, got 'yes'"},
      {"SppZero", kPath + "spp 0\n", 4, "'spp' argument 1: expected an integer from 1 to 1000000000, got '0'"},
      {"SppNegative", kPath + "spp -4\n", 4, "'spp' argument 1: expected an integer from 1 to 1000000000, got '-4'"},
      {"GammaZero", kPath + "gamma 0\n", 4, "gamma must be positive, got '0'"},
      {"GammaNegative", kPath + "gamma -2.2\n", 4, "gamma must be positive, got '-2.2'"},
      {"RoughnessNegative", kPath + "roughness -0.1\n", 4, "roughness must not be negative, got '-0.1'"},
      {"UnknownNextEvent", kPath + "nexteventestimation yes\n", 4,
       "'nexteventestimation' argument 1: expected off, on or mis, got 'yes'"},
      {"UnknownRussianRoulette", kPath + "russianroulette 1\n", 4, "'russianroulette' argument 1: expected on or off, got '1'"},
      {"UnknownImportanceSampling", kPath + "importancesampling uniform\n", 4,
       "'importancesampling' argument 1: expected hemisphere, cosine or brdf, got 'uniform'"},
      {"UnknownBrdf", kPath + "brdf blinn\n", 4, "'brdf' argument 1: expected phong or ggx, got 'blinn'"},
      {"QuadLightMissingArguments", kPath + "quadLight 0 0 0 1 0 0 0 1 0\n", 4,
       "'quadLight' expects 12 arguments (ax ay az abx aby abz acx acy acz r g b), got 9"},
      {"QuadLightDegenerate", kPath + "quadLight 0 0 0 1 0 0 2 0 0 1 1 1\n", 4,
       "degenerate quadLight: its sides ab and ac span no area"},
      {"QuadLightDegenerateUnderTransform", kPath + "scale 1 0 1\nquadLight 0 0 0 1 0 0 0 1 0 1 1 1\n", 5,
       "degenerate quadLight: its sides ab and ac span no area (under the current transform)"},
  };
}

// gtest prints this instead of the struct's bytes.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

class ParseError : public ::testing::TestWithParam<BadInput> {};

}  // namespace

TEST_P(ParseError, ParserReportsFileLineAndMessage) {
  const BadInput& c = GetParam();
  try {
    SceneDesc s = parseScene(c.text, "bad.test");
    // Output problems are found when the output is resolved, before rendering.
    resolveOutput(s, RenderRequest{});
    FAIL() << "no error for " << c.name;
  } catch (const SceneError& e) {
    auto firstError = std::find_if(e.diagnostics().begin(), e.diagnostics().end(),
                                   [](const Diagnostic& d) { return d.isError(); });
    ASSERT_NE(firstError, e.diagnostics().end()) << e.what();
    const Diagnostic& d = *firstError;
    EXPECT_EQ(d.file, "bad.test");
    EXPECT_EQ(d.line, c.line) << e.what();
    EXPECT_NE(d.message.find(c.message), std::string::npos) << "message: " << d.message;
  }
}

TEST_P(ParseError, CliExitsWithStatus2AndWritesNothing) {
  const BadInput& c = GetParam();
  std::string dir = freshDir(std::string("parse-errors/") + c.name);
  std::string scene = dir + "/bad.test";
  writeFile(scene, c.text);
  // An image the user already had, under the name the render would write: it must survive.
  std::string existing = dir + "/precious.png";
  writeFile(existing, "precious");
  // The scene's own `output` is the target of the Output* cases; -o is for all the others.
  bool ownOutput = std::string(c.name).rfind("Output", 0) == 0;
  RunResult r = runVkrt("-q '" + scene + "'" + (ownOutput ? std::string() : " -o '" + existing + "'"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  std::string expected = scene + ":" + std::to_string(c.line) + ": error: ";
  EXPECT_NE(r.output.find(expected), std::string::npos) << "expected '" << expected << "' in:\n" << r.output;
  EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
  EXPECT_EQ(readFile(existing), "precious");
  EXPECT_EQ(fileCount(dir), 2u) << "a file was written beside the scene";
}

INSTANTIATE_TEST_SUITE_P(Section8, ParseError, ::testing::ValuesIn(badInputs()),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(ParseErrors, AllProblemsAreReportedInOneRun) {
  try {
    parseScene(kOk + "vertex 1 2\nfoo\nrotate 0 0 0 1\n", "multi.test");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), 3u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].line, 3);
    EXPECT_EQ(e.diagnostics()[1].line, 4);
    EXPECT_EQ(e.diagnostics()[2].line, 5);
    EXPECT_EQ(std::string(e.what()),
              "multi.test:3: error: 'vertex' expects 3 arguments (x y z), got 2\n"
              "multi.test:4: warning: unknown command 'foo' (line skipped)\n"
              "multi.test:5: error: rotate axis must not be zero");
  }
}

// With -q the errors are printed and the warnings beside them are not; with --strict the
// warnings are errors and always printed.
TEST(ParseErrors, QuietLeavesOutTheWarningsButNotTheErrors) {
  std::string dir = freshDir("parse-errors/quiet");
  writeFile(dir + "/bad.test", kOk + "foo\nrotate 0 0 0 1\n");
  RunResult loud = runVkrt("--backend cpu -o " + dir + "/o.png " + dir + "/bad.test");
  EXPECT_EQ(loud.exitCode, 2) << loud.output;
  EXPECT_NE(loud.output.find("bad.test:3: warning: unknown command 'foo'"), std::string::npos) << loud.output;
  EXPECT_NE(loud.output.find("bad.test:4: error: rotate axis"), std::string::npos) << loud.output;
  RunResult quiet = runVkrt("-q --backend cpu -o " + dir + "/o.png " + dir + "/bad.test");
  EXPECT_EQ(quiet.exitCode, 2) << quiet.output;
  EXPECT_EQ(quiet.output, dir + "/bad.test:4: error: rotate axis must not be zero\n");
  RunResult strict = runVkrt("-q --strict --backend cpu -o " + dir + "/o.png " + dir + "/bad.test");
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  EXPECT_NE(strict.output.find("bad.test:3: error: unknown command 'foo' (line skipped) [--strict]"),
            std::string::npos)
      << strict.output;
  EXPECT_FALSE(fileExists(dir + "/o.png"));
}

TEST(ParseErrors, ManyErrorsStopAtALimit) {
  std::string text = kOk;
  for (int i = 0; i < 1000; ++i) text += "vertex 1\n";
  try {
    parseScene(text, "many.test");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_LE(e.diagnostics().size(), 51u);
    EXPECT_NE(std::string(e.what()).find("too many errors"), std::string::npos);
  }
}

// A scene file that cannot be read is an I/O error (exit 4), not a scene error.
TEST(ParseErrors, MissingSceneFileIsAnIoError) {
  RunResult r = runVkrt("-q no-such-scene.test");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("vkrt: error: cannot open scene file 'no-such-scene.test': No such file or directory"),
            std::string::npos)
      << r.output;
  EXPECT_THROW(parseSceneFile("no-such-scene.test"), IoError);
}
