// What real files do and vkrt accepts with a warning (doc/scene-format.md, "Warnings and errors"): one case per kind,
// checking the message, its line and that the scene was read as its author meant; with
// --strict each one is an error (exit 2, nothing written). Parsed from strings.
#include <algorithm>
#include <filesystem>
#include <functional>

#include <gtest/gtest.h>

#include "image/image_file.h"   // outputNameProblem
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kOk = "size 64 48\ncamera 0 0 5 0 0 0 0 1 0 45\n";   // lines 1-2

struct Accepted {
  const char* name;
  std::string text;
  int line;              // expected line of the (first) warning
  const char* message;   // expected part of its message
  std::function<void(const SceneDesc&)> check;   // the scene as its author meant it
};

std::vector<Accepted> acceptedInputs() {
  return {
      {"UnknownCommand", kOk + "refraction 1.5\nsphere 0 0 0 1\n", 3, "unknown command 'refraction' (line skipped)",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"UnknownCommandWithNumbers", kOk + "area 0 0 1 1 1 1 0.5\nsphere 0 0 0 1\n", 3, "unknown command 'area'",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"KeywordCaseMaxDepth", kOk + "maxDepth 3\n", 3, "'maxDepth' read as 'maxdepth' (keywords are case-sensitive)",
       [](const SceneDesc& s) { EXPECT_EQ(s.maxDepth, 3); }},
      {"KeywordCaseTransforms", kOk + "vertex 1 0 0\npushTransform\ntranslate 5 0 0\nPopTransform\ntri 0 0 0\n", 6,
       "'PopTransform' read as 'popTransform'",
       [](const SceneDesc& s) {
         ASSERT_EQ(s.triangles.size(), 1u);
         EXPECT_EQ(s.triangles[0].p[0], dvec3(1, 0, 0));   // the pop restored the transform
       }},
      {"KeywordCaseSize", "SIZE 20 10\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1, "'SIZE' read as 'size'",
       [](const SceneDesc& s) { EXPECT_EQ(s.width, 20); }},
      // A shape's own command (shapes/shape_list.h) is looked up as every other command is.
      {"KeywordCaseShapeCommand", kOk + "Sphere 0 0 0 2\n", 3, "'Sphere' read as 'sphere' (keywords are case-sensitive)",
       [](const SceneDesc& s) {
         ASSERT_EQ(s.spheres.size(), 1u);
         EXPECT_EQ(s.spheres[0].radius, 2.0);
       }},
      {"ShapeCommandBeforeSize", "sphere 0 0 0 1\nsize 64 48\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1,
       "'sphere' before 'size' (line 2)", [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"RepeatedSize", kOk + "size 32 16\n", 3, "'size' given again (before at line 1): the last one counts",
       [](const SceneDesc& s) {
         EXPECT_EQ(s.width, 32);
         EXPECT_EQ(s.height, 16);
         EXPECT_EQ(s.sizeLine, 3);
       }},
      {"RepeatedCamera", kOk + "camera 0 0 9 0 0 0 0 1 0 60\n", 3, "'camera' given again (before at line 2)",
       [](const SceneDesc& s) {
         EXPECT_EQ(s.camera.from, dvec3(0, 0, 9));
         EXPECT_EQ(s.camera.fovyDegrees, 60.0);
       }},
      {"RepeatedMaxDepth", kOk + "maxdepth 2\nmaxdepth 7\n", 4, "'maxdepth' given again (before at line 3)",
       [](const SceneDesc& s) { EXPECT_EQ(s.maxDepth, 7); }},
      {"RepeatedOutput", kOk + "output a.png\noutput b.png\n", 4, "'output' given again (before at line 3)",
       [](const SceneDesc& s) {
         EXPECT_EQ(s.output, "b.png");
         EXPECT_EQ(s.outputLine, 4);
       }},
      {"OutputBeforeSize", "output first.png\nmaxdepth 2\nsize 64 48\ncamera 0 0 5 0 0 0 0 1 0 45\n", 1,
       "'output' before 'size' (line 3): accepted",
       [](const SceneDesc& s) {
         EXPECT_EQ(s.output, "first.png");
         EXPECT_EQ(s.maxDepth, 2);
         EXPECT_EQ(s.width, 64);
       }},
      {"CameraBeforeSize", "camera 0 0 5 0 0 0 0 1 0 45\nsize 64 48\n", 1, "'camera' before 'size' (line 2)",
       [](const SceneDesc& s) { EXPECT_EQ(s.camera.from, dvec3(0, 0, 5)); }},
      {"ExtraArguments", kOk + "sphere 0 0 0 1 2\n", 3,
       "'sphere' takes 4 arguments (x y z radius), got 5: the extra one is ignored",
       [](const SceneDesc& s) {
         ASSERT_EQ(s.spheres.size(), 1u);
         EXPECT_EQ(s.spheres[0].radius, 1.0);
       }},
      {"ExtraArgumentsToPush", kOk + "pushTransform 1 2\ntranslate 1 0 0\npopTransform\nsphere 0 0 0 1\n", 3,
       "'pushTransform' takes no arguments, got 2: the extra 2 are ignored",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres[0].worldFromObject, dmat4(1.0)); }},
      {"ExtraArgumentsToOutput", kOk + "output a.png b.png\n", 3, "'output' takes 1 argument",
       [](const SceneDesc& s) { EXPECT_EQ(s.output, "a.png"); }},
      {"OutputNotPngOrPpm", kOk + "output render.bmp\n", 3,
       "output file 'render.bmp' is not named .png, .ppm, .pfm or .exr: vkrt writes PNG, under that name",
       [](const SceneDesc& s) { EXPECT_EQ(s.output, "render.bmp"); }},
      {"OutputWithoutExtension", kOk + "output out.d/render\n", 3,
       "output file 'out.d/render' is not named .png, .ppm, .pfm or .exr",
       [](const SceneDesc& s) { EXPECT_EQ(s.output, "out.d/render"); }},
      // doc/path-tracing.md, "Commands": what the scene's integrator does not use is ignored (the
      // setting keeps its default), decided at the end of file.
      {"SppUnderRaytracer", kOk + "spp 16\n", 3, "'spp' ignored: integrator raytracer (the default) does not use it",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.spp, 1); }},
      {"GammaUnderRaytracer", kOk + "gamma 2.2\n", 3, "'gamma' ignored: integrator raytracer (the default)",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.gamma, 1.0); }},
      {"LightSamplesUnderRaytracer", kOk + "lightsamples 4\n", 3, "'lightsamples' ignored: integrator raytracer",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.lightSamples, 1); }},
      {"LightStratifyUnderRaytracer", kOk + "integrator raytracer\nlightstratify on\n", 4,
       "'lightstratify' ignored: integrator raytracer (line 3) does not use it",
       [](const SceneDesc& s) { EXPECT_FALSE(s.path.lightStratify); }},
      {"NextEventUnderRaytracer", kOk + "nexteventestimation mis\n", 3, "'nexteventestimation' ignored",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.nextEvent, NextEvent::Off); }},
      {"RussianRouletteUnderRaytracer", kOk + "russianroulette on\n", 3, "'russianroulette' ignored",
       [](const SceneDesc& s) { EXPECT_FALSE(s.path.russianRoulette); }},
      {"ImportanceSamplingUnderRaytracer", kOk + "importancesampling cosine\n", 3, "'importancesampling' ignored",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.sampling, Sampling::Hemisphere); }},
      {"BrdfUnderRaytracer", kOk + "brdf ggx\nsphere 0 0 0 1\n", 3, "'brdf' ignored: integrator raytracer",
       [](const SceneDesc& s) { EXPECT_EQ(s.materials[s.spheres[0].material].brdf, BrdfModel::Phong); }},
      {"RoughnessUnderRaytracer", kOk + "roughness 0.3\nsphere 0 0 0 1\n", 3, "'roughness' ignored",
       [](const SceneDesc& s) { EXPECT_EQ(s.materials[s.spheres[0].material].roughness, 0.0); }},
      {"QuadLightUnderRaytracer", kOk + "quadLight -1 1 -1 0 0 2 2 0 0 5 5 5\nsphere 0 0 0 1\n", 3,
       "'quadLight' ignored: integrator raytracer (the default) does not use it (the Whitted model has no area lights)",
       [](const SceneDesc& s) {
         EXPECT_TRUE(s.quadLights.empty());
         EXPECT_TRUE(s.triangles.empty());
         EXPECT_EQ(s.materials.size(), 1u);
       }},
      {"QuadLightThenRaytracer", kOk + "quadLight -1 1 -1 0 0 2 2 0 0 5 5 5\nintegrator raytracer\n", 3,
       "'quadLight' ignored: integrator raytracer (line 4) does not use it",
       [](const SceneDesc& s) { EXPECT_TRUE(s.triangles.empty()); }},
      {"NextEventUnderDirect", kOk + "integrator direct\nnexteventestimation on\n", 4,
       "'nexteventestimation' ignored: integrator direct (line 3) does not use it",
       [](const SceneDesc& s) {
         EXPECT_EQ(s.path.integrator, Integrator::Direct);
         EXPECT_EQ(s.path.nextEvent, NextEvent::Off);
       }},
      {"LightSamplesUnderAnalyticDirect", kOk + "lightsamples 9\nintegrator analyticdirect\n", 3,
       "'lightsamples' ignored: integrator analyticdirect (line 4) does not use it",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.lightSamples, 1); }},
      {"BrdfUnderAnalyticDirect", kOk + "integrator analyticdirect\nbrdf ggx\nsphere 0 0 0 1\n", 4,
       "'brdf' ignored: integrator analyticdirect",
       [](const SceneDesc& s) { EXPECT_EQ(s.materials[s.spheres[0].material].brdf, BrdfModel::Phong); }},
      {"KeywordValueInAnotherCase", kOk + "integrator PathTracer\n", 3,
       "'PathTracer' read as 'pathtracer' (keywords are case-sensitive)",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.integrator, Integrator::PathTracer); }},
      {"OnOffInAnotherCase", kOk + "integrator pathtracer\nrussianroulette ON\n", 4, "'ON' read as 'on'",
       [](const SceneDesc& s) { EXPECT_TRUE(s.path.russianRoulette); }},
      {"KeywordCaseQuadLight", kOk + "integrator direct\nquadlight 0 0 0 1 0 0 0 1 0 1 1 1\n", 4,
       "'quadlight' read as 'quadLight'",
       [](const SceneDesc& s) { EXPECT_EQ(s.quadLights.size(), 1u); }},
      // A scene-wide path setting given again: the last one counts, as for size or camera.
      {"RepeatedSpp", kOk + "integrator pathtracer\nspp 4\nspp 16\n", 5,
       "'spp' given again (before at line 4): the last one counts",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.spp, 16); }},
      {"RepeatedNextEventEstimation", kOk + "integrator pathtracer\nnexteventestimation on\ngamma 2\nnexteventestimation mis\n",
       6, "'nexteventestimation' given again (before at line 4)",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.nextEvent, NextEvent::Mis); }},
      {"RepeatedGamma", kOk + "integrator pathtracer\ngamma 2\ngamma 2.2\n", 5,
       "'gamma' given again (before at line 4): the last one counts",
       [](const SceneDesc& s) { EXPECT_DOUBLE_EQ(s.path.gamma, 2.2); }},
      {"RepeatedIntegrator", kOk + "integrator direct\nintegrator pathtracer\n", 4,
       "'integrator' given again (before at line 3): the last one counts",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.integrator, Integrator::PathTracer); }},
      // Nothing but Russian roulette ends a path that stays in the scene under `maxdepth -1`.
      {"UnlimitedDepthWithoutRoulette", kOk + "integrator pathtracer\nmaxdepth -1\n", 4,
       "'maxdepth -1' (no limit) with 'russianroulette off': a path ends only when it leaves the scene",
       [](const SceneDesc& s) { EXPECT_EQ(s.maxDepth, -1); }},
      {"UnlimitedDepthRouletteOff", kOk + "maxdepth -1\nintegrator pathtracer\nrussianroulette off\n", 3,
       "'maxdepth -1' (no limit) with 'russianroulette off'",
       [](const SceneDesc& s) { EXPECT_FALSE(s.path.russianRoulette); }},
      // Coordinates beyond 1e153: squares of lengths near the largest double (a sphere of
      // radius 2e154 around the camera renders wrong on the CPU backend).
      {"SphereBeyondTheExactRange", kOk + "sphere 0 0 0 1e160\n", 3,
       "'sphere' reaches coordinates of 1e+160, beyond 1e153, where squares of lengths come near the largest double",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"TriangleScaledBeyondTheExactRange", kOk + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nscale 3e153 1 1\ntri 0 1 2\n",
       7, "'tri' reaches coordinates of 3e+153, beyond 1e153",
       [](const SceneDesc& s) { EXPECT_EQ(s.triangles.size(), 1u); }},
      {"CameraBeyondTheExactRange", "size 64 48\ncamera 0 0 -5e155 0 0 0 0 1 0 45\n", 2,
       "'camera' reaches coordinates of 5e+155, beyond 1e153",
       [](const SceneDesc& s) { EXPECT_EQ(s.camera.from.z, -5e155); }},
      // Shapes less than 1e-153 across: squares of lengths below the smallest normal double (a
      // sphere of radius 1e-162 around the camera renders wrong on the CPU backend).
      {"SphereBelowTheExactSize", kOk + "sphere 0 0 0 1e-200\n", 3,
       "'sphere' is 2e-200 across, below 1e-153, where squares of lengths fall below the smallest normal double",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"TriangleScaledBelowTheExactSize",
       kOk + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nscale 1e-160 1e-160 1e-160\ntri 0 1 2\n", 7,
       "'tri' is 1e-160 across, below 1e-153",
       [](const SceneDesc& s) { EXPECT_EQ(s.triangles.size(), 1u); }},
      // A sphere scaled to those sizes: its box without squares that overflow or underflow.
      {"SphereScaledBeyondTheExactRange", kOk + "scale 1e160 1 1\nsphere 0 0 0 1\n", 4,
       "'sphere' reaches coordinates of 1e+160, beyond 1e153",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"SphereScaledBelowTheExactSize", kOk + "scale 1e-160 1e-160 1e-160\nsphere 0 0 0 1\n", 4,
       "'sphere' is 2e-160 across, below 1e-153",
       [](const SceneDesc& s) { EXPECT_EQ(s.spheres.size(), 1u); }},
      {"ExtraArgumentsToIntegrator", kOk + "integrator direct fast\n", 3,
       "'integrator' takes 1 argument (raytracer, analyticdirect, direct or pathtracer), got 2: the extra one is ignored",
       [](const SceneDesc& s) { EXPECT_EQ(s.path.integrator, Integrator::Direct); }},
  };
}

void PrintTo(const Accepted& c, std::ostream* os) { *os << c.name; }

class ParseWarning : public ::testing::TestWithParam<Accepted> {};

}  // namespace

TEST_P(ParseWarning, ParsedAsMeantWithALocatedWarning) {
  const Accepted& c = GetParam();
  // (The output name is judged as the render judges it: by the image formats' rules.)
  ParsedScene p = parseSceneWithWarnings(c.text, "w.test", ParseOptions{false, false, outputNameProblem});
  ASSERT_EQ(p.warnings.size(), 1u) << c.name;
  const Diagnostic& w = p.warnings.front();
  EXPECT_EQ(w.severity, Severity::Warning);
  EXPECT_EQ(w.file, "w.test");
  EXPECT_EQ(w.line, c.line) << w.format();
  EXPECT_NE(w.message.find(c.message), std::string::npos) << "message: " << w.message;
  EXPECT_EQ(w.format().rfind("w.test:" + std::to_string(c.line) + ": warning: ", 0), 0u) << w.format();
  c.check(p.scene);
}

TEST_P(ParseWarning, StrictMakesItAnError) {
  const Accepted& c = GetParam();
  try {
    parseSceneWithWarnings(c.text, "w.test", ParseOptions{true, false, outputNameProblem});
    FAIL() << "no error with --strict for " << c.name;
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    const Diagnostic& d = e.diagnostics().front();
    EXPECT_TRUE(d.isError());
    EXPECT_EQ(d.line, c.line);
    EXPECT_NE(d.message.find(c.message), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("[--strict]"), std::string::npos) << d.message;
  }
}

// Through the CLI: the warning on stderr and the image written; with --strict exit 2, the
// message as an error, nothing written and an existing image untouched.
TEST_P(ParseWarning, CliWarnsAndRendersButStrictRefuses) {
  const Accepted& c = GetParam();
  std::string dir = freshDir(std::string("parse-warnings/") + c.name);
  std::string scene = dir + "/w.test";
  writeFile(scene, c.text);
  // Into the folder (-o DIR/), under the scene's output name: -o FILE would replace an
  // `output` line, which then draws no warning.
  RunResult r = runVkrt("--backend cpu -o '" + dir + "/' '" + scene + "'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::string expected = scene + ":" + std::to_string(c.line) + ": warning: ";
  EXPECT_NE(r.output.find(expected + c.message), std::string::npos) << "expected '" << expected << "' in:\n"
                                                                    << r.output;
  std::string image;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path() != scene) image = entry.path().string();
  ASSERT_FALSE(image.empty()) << "no image written";

  writeFile(image, "precious");
  RunResult strict = runVkrt("--strict --backend cpu -o '" + dir + "/' '" + scene + "'");
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  EXPECT_NE(strict.output.find(scene + ":" + std::to_string(c.line) + ": error: " + c.message), std::string::npos)
      << strict.output;
  EXPECT_EQ(readFile(image), "precious");
  EXPECT_EQ(fileCount(dir), 2u) << "a file was written beside the scene";
}

INSTANTIATE_TEST_SUITE_P(Section8, ParseWarning, ::testing::ValuesIn(acceptedInputs()),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(ParseWarnings, OfThreeSizesTheLastCounts) {
  ParsedScene p = parseSceneWithWarnings(kOk + "size 20 10\nsize 32 16\n", "w.test");
  EXPECT_EQ(p.scene.width, 32);
  EXPECT_EQ(p.scene.height, 16);
  EXPECT_EQ(p.scene.sizeLine, 4);
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_EQ(p.warnings[0].format(), "w.test:3: warning: 'size' given again (before at line 1): the last one counts");
  EXPECT_EQ(p.warnings[1].format(), "w.test:4: warning: 'size' given again (before at line 3): the last one counts");
}

// Another course's keywords in other cases: each read as the keyword, each said once.
TEST(ParseWarnings, KeywordsInAnyCase) {
  ParsedScene p = parseSceneWithWarnings(
      kOk + "maxVerts 3\nVertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nDIFFUSE 1 0 0\nTri 0 1 2\npoint 0 0 5 1 1 1\n",
      "w.test");
  ASSERT_EQ(p.scene.triangles.size(), 1u);
  EXPECT_EQ(p.scene.materials[p.scene.triangles[0].material].diffuse, dvec3(1, 0, 0));
  ASSERT_EQ(p.warnings.size(), static_cast<std::size_t>(kMaxWarningsPerKind + 1));   // 4 of one kind
  EXPECT_EQ(p.warnings[0].message, "'maxVerts' read as 'maxverts' (keywords are case-sensitive)");
  EXPECT_EQ(p.warnings[3].message, "... and 1 more of this kind (keywords in another case), on line 8");
}

// Commands the integrator does not use are one kind, summarised like the others, at their
// lines, though found only at the end of file.
TEST(ParseWarnings, IgnoredPathCommandsAreSummarised) {
  ParsedScene p = parseSceneWithWarnings(kOk + "spp 4\ngamma 2\nbrdf ggx\nroughness 1\nlightsamples 4\nsphere 0 0 0 1\n",
                                         "w.test");
  ASSERT_EQ(p.warnings.size(), static_cast<std::size_t>(kMaxWarningsPerKind + 1));
  for (int i = 0; i < kMaxWarningsPerKind; ++i) EXPECT_EQ(p.warnings[i].line, 3 + i);
  EXPECT_EQ(p.warnings.back().format(), "w.test:6: warning: ... and 2 more of this kind (commands the integrator "
                                        "does not use), on lines 6 to 7");
}

TEST(ParseWarnings, ByteOrderMarkIsSkippedSilently) {
  const std::string bom = "\xEF\xBB\xBF";
  for (const std::string& text :
       {bom + kOk, bom + "size 64 48\r\ncamera 0 0 5 0 0 0 0 1 0 45\r\n", bom + "# a comment first\n" + kOk}) {
    ParsedScene p = parseSceneWithWarnings(text, "bom.test", ParseOptions{true});
    EXPECT_TRUE(p.warnings.empty());
    EXPECT_EQ(p.scene.width, 64);
    EXPECT_EQ(p.scene.camera.from, dvec3(0, 0, 5));
  }
}

// A file whose lines end in CR alone (classic Mac OS) is the same scene as with LF, with one
// warning at line 1 (an error under --strict); an error in it names its own line. A lone CR
// at the very end of a one-line file, or a CR inside an LF file, changes nothing.
TEST(ParseWarnings, LinesEndingInCrAloneAreLines) {
  std::string mac = kOk + "sphere 0 0 0 1\n";
  std::replace(mac.begin(), mac.end(), '\n', '\r');
  ParsedScene p = parseSceneWithWarnings(mac, "mac.test");
  ParsedScene unix = parseSceneWithWarnings(kOk + "sphere 0 0 0 1\n", "unix.test");
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0].format(),
            "mac.test:1: warning: the lines end in CR alone (classic Mac OS), not LF or CRLF: each CR read as a line end");
  EXPECT_EQ(p.scene.width, unix.scene.width);
  EXPECT_EQ(p.scene.camera.from, unix.scene.camera.from);
  EXPECT_EQ(p.scene.spheres.size(), 1u);
  EXPECT_THROW(parseSceneWithWarnings(mac, "mac.test", ParseOptions{true}), SceneError);
  try {
    parseSceneWithWarnings("size 64 48\rcamera 0 0 5 0 0 0 0 1 0 45\rsphere 0 0\r", "bad.test");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.test:3: error:"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(parseSceneWithWarnings(kOk + "sphere 0 0 0 1\r", "end.test").warnings.empty());
}

TEST(ParseWarnings, CleanFilesHaveNone) {
  EXPECT_TRUE(parseSceneWithWarnings(kOk + "maxdepth 2\noutput x.PNG\nsphere 0 0 0 1\n", "ok.test").warnings.empty());
  EXPECT_TRUE(parseSceneWithWarnings(kOk + "output render.ppm\n", "ok.test").warnings.empty());   // written as PPM
  EXPECT_TRUE(parseSceneWithWarnings(kOk + "output RENDER.PPM\n", "ok.test").warnings.empty());
  // Material state and lights repeat without a warning: each shape takes the current one.
  EXPECT_TRUE(parseSceneWithWarnings(kOk + "integrator pathtracer\nbrdf ggx\nroughness 0.3\nsphere 0 0 0 1\n"
                                           "brdf phong\nroughness 0.5\nsphere 2 0 0 1\n"
                                           "quadLight 0 3 0 1 0 0 0 0 1 5 5 5\nquadLight 2 3 0 1 0 0 0 0 1 5 5 5\n",
                                     "ok.test").warnings.empty());
  // Up to 1e153, and down to 1e-153 across: the picture follows the scene (doc/robustness.md);
  // a point (a sphere of radius 0) is no shape of lost precision.
  EXPECT_TRUE(parseSceneWithWarnings("size 64 48\ncamera 0 0 1e153 0 0 0 0 1 0 45\nsphere 0 0 0 1e153\n"
                                     "sphere 0 0 0 1e-153\nsphere 1e-200 0 0 0\n", "ok.test").warnings.empty());
  for (const std::string& name : projectSceneNames()) {
    ParsedScene p = parseSceneFileWithWarnings(sourcePath("scenes/" + name + ".test"));
    EXPECT_TRUE(p.warnings.empty()) << name << ": " << p.warnings.front().format();
  }
  if (auto dir = cse167Dir()) {
    for (const auto& e : std::filesystem::directory_iterator(*dir + "/scenes")) {
      if (e.path().extension() != ".test") continue;
      ParsedScene p = parseSceneFileWithWarnings(e.path().string());
      EXPECT_TRUE(p.warnings.empty()) << e.path() << ": " << p.warnings.front().format();
    }
  }
}

// Messages quote what the file says with its non-printable bytes escaped, never raw: a
// byte-order mark in the middle of a file, UTF-8, bytes of no encoding.
TEST(ParseWarnings, MessagesEscapeNonPrintableBytes) {
  ParsedScene p = parseSceneWithWarnings(kOk + "\xEF\xBB\xBFsphere 0 0 0 1\ncam\xC3\xA9ra 1\n", "w.test");
  ASSERT_EQ(p.warnings.size(), 2u);
  EXPECT_EQ(p.warnings[0].message, "unknown command '\\xEF\\xBB\\xBFsphere' (line skipped)");
  EXPECT_EQ(p.warnings[1].message, "unknown command 'cam\\xC3\\xA9ra' (line skipped); did you mean 'camera'?");
  try {
    parseScene(kOk + "vertex 1 \xFF\xFE 0\n", "e.test");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "e.test:3: error: 'vertex' argument 2: expected a number, got '\\xFF\\xFE'");
  }
}

TEST(ParseWarnings, RepeatsOfOneKindAreSummarisedAfterTheFirstFew) {
  std::string text = kOk;
  for (int i = 0; i < 10; ++i) text += "antialias 4\n";   // lines 3-12
  text += "Sphere 0 0 0 1\nSphere 1 0 0 1\n";            // another kind: listed on its own
  ParsedScene p = parseSceneWithWarnings(text, "w.test");
  EXPECT_EQ(p.scene.spheres.size(), 2u);
  ASSERT_EQ(p.warnings.size(), static_cast<std::size_t>(kMaxWarningsPerKind + 1 + 2));
  for (int i = 0; i < kMaxWarningsPerKind; ++i) EXPECT_EQ(p.warnings[i].line, 3 + i);
  const Diagnostic& summary = p.warnings[kMaxWarningsPerKind];
  EXPECT_EQ(summary.line, 3 + kMaxWarningsPerKind);
  EXPECT_EQ(summary.format(), "w.test:6: warning: ... and 7 more of this kind (unknown commands), on lines 6 to 12");
  EXPECT_EQ(p.warnings[4].line, 13);
  EXPECT_EQ(p.warnings[5].line, 14);
}

TEST(ParseWarnings, AFileOfUnknownCommandsParsesWithFourWarnings) {
  std::string text = kOk;
  for (int i = 0; i < 100000; ++i) text += "vt 0.5 0.5\n";
  ParsedScene p = parseSceneWithWarnings(text, "obj.test");
  ASSERT_EQ(p.warnings.size(), 4u);
  EXPECT_NE(p.warnings.back().message.find("99997 more"), std::string::npos) << p.warnings.back().message;
}

// Errors stay errors, and the SceneError lists the warnings beside them, in line order.
TEST(ParseWarnings, ErrorsStayErrorsAndWarningsComeWithThem) {
  try {
    parseSceneWithWarnings("maxdepth 2\nsize 64 48\nrefraction 1\nmaxdepth -1\ncamera 0 0 5 0 0 0 0 1 0 45\n"
                           "vertex 1 nan 0\n",
                           "e.test");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "e.test:1: warning: 'maxdepth' before 'size' (line 2): accepted, though the format puts 'size' first\n"
              "e.test:3: warning: unknown command 'refraction' (line skipped)\n"
              "e.test:4: warning: 'maxdepth' given again (before at line 1): the last one counts\n"
              "e.test:4: error: 'maxdepth' argument 1: expected a non-negative integer, got '-1': -1 (no limit) is "
              "for the path integrators, and integrator raytracer (the default) is the Whitted model\n"
              "e.test:6: error: 'vertex' argument 2: expected a finite number, got 'nan'");
  }
  // No size at all is an error, and then commands before it are not warned about.
  try {
    parseSceneWithWarnings("output a.png\ncamera 0 0 5 0 0 0 0 1 0 45\n", "e.test");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_NE(e.diagnostics()[0].message.find("no 'size' command"), std::string::npos);
  }
}
