// The warnings that help and the counts that read right: a Whitted scene that no light
// reaches, the --stats line's lights by kind, --compare's breakdowns only with --stats, and
// one noun in the right number wherever a count is printed.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "util/counted.h"
#include "util/errors.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/radiance_image.h"
#include "image/samples.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const std::string kHead = "size 16 12\ncamera 0 0 5 0 0 0 0 1 0 45\n";   // lines 1-2
const char* kNoLights = "the scene has no lights: only ambient and emission light it";

std::vector<Diagnostic> noLightWarnings(const std::string& text) {
  std::vector<Diagnostic> found;
  for (const Diagnostic& w : parseSceneWithWarnings(text, "s.test").warnings)
    if (w.message.find(kNoLights) != std::string::npos) found.push_back(w);
  return found;
}

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(Counted, SaysOneAndMany) {
  EXPECT_EQ(counted(0, "batch", "batches"), "0 batches");
  EXPECT_EQ(counted(1, "batch", "batches"), "1 batch");
  EXPECT_EQ(counted(2u, "batch", "batches"), "2 batches");
  EXPECT_EQ(counted(std::size_t{1}, "light", "lights"), "1 light");
}

// Diffuse and specular colours with no light to show them: a warning at the `size` line that
// names the first such surface; with --strict, an error.
TEST(NoLightsWarning, WhittedSceneWithShadedSurfacesAndNoLight) {
  const std::string text = kHead + "ambient 0.1 0.1 0.1\ndiffuse 1 0 0\nsphere 0 0 0 1\n";
  std::vector<Diagnostic> w = noLightWarnings(text);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].line, 1);
  EXPECT_FALSE(w[0].isError());
  EXPECT_NE(w[0].message.find("(the first at line 5)"), std::string::npos) << w[0].message;
  EXPECT_EQ(w[0].message.find("quad"), std::string::npos) << w[0].message;
  EXPECT_THROW(parseSceneWithWarnings(text, "s.test", ParseOptions{true}), SceneError);
  EXPECT_EQ(noLightWarnings(kHead + "specular 1 1 1\nsphere 0 0 0 1\n").size(), 1u);
}

// A quad light is no light to the Whitted model (it is ignored): the warning says so.
TEST(NoLightsWarning, WhittedQuadLightIsNoLight) {
  const std::string quad = "quadLight -1 2 -1 2 0 0 0 0 2 5 5 5\n";
  std::vector<Diagnostic> w = noLightWarnings(kHead + "diffuse 1 1 1\nsphere 0 0 0 1\n" + quad);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].message.find("its 1 quad light is ignored: the Whitted model has no area lights"), std::string::npos)
      << w[0].message;
  w = noLightWarnings(kHead + "diffuse 1 1 1\nsphere 0 0 0 1\n" + quad + quad);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].message.find("its 2 quad lights are ignored"), std::string::npos) << w[0].message;
  // The path integrators' light.
  for (const char* integrator : {"analyticdirect", "direct", "pathtracer"})
    EXPECT_EQ(noLightWarnings(kHead + "integrator " + integrator + "\ndiffuse 1 1 1\nsphere 0 0 0 1\n" + quad).size(),
              0u)
        << integrator;
}

// What needs no warning: a point or directional light, surfaces coloured by ambient and
// emission alone (lights would change nothing), no surface at all.
TEST(NoLightsWarning, NotWhereALightWouldChangeNothing) {
  const std::string shaded = "diffuse 1 1 1\nsphere 0 0 0 1\n";
  EXPECT_EQ(noLightWarnings(kHead + "point 0 5 5 1 1 1\n" + shaded).size(), 0u);
  EXPECT_EQ(noLightWarnings(kHead + shaded + "directional 0 0 1 1 1 1\n").size(), 0u);
  EXPECT_EQ(noLightWarnings(kHead + "ambient 1 0 0\nemission 0 1 0\nsphere 0 0 0 1\n").size(), 0u);
  EXPECT_EQ(noLightWarnings(kHead + "diffuse 1 1 1\n").size(), 0u);
}

// The course's scenes: scene2 and scene3 have no light and colour their surfaces with
// ambient alone, as their comments say; none of the ten gets the warning.
TEST(NoLightsWarning, NoCourseSceneGetsIt) {
  auto dir = cse167Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse167Data);
  for (const char* name : {"scene1", "scene2", "scene3", "scene4-ambient", "scene4-diffuse", "scene4-emission",
                           "scene4-specular", "scene5", "scene6", "scene7"}) {
    ParsedScene p = parseSceneFileWithWarnings(*dir + "/scenes/" + name + ".test", ParseOptions{true});
    EXPECT_TRUE(p.warnings.empty()) << name;
  }
}

// The --stats line counts each kind of light, and says one light, one thread.
TEST(StatsLine, CountsLightsByKind) {
  std::string dir = freshDir("warnings/stats");
  writeFile(dir + "/whitted.test", kHead + "point 0 5 5 1 1 1\ndirectional 0 0 1 1 1 1\npoint 5 0 5 1 1 1\n"
                                           "diffuse 1 1 1\nsphere 0 0 0 1\n");
  RunResult r = runVkrt("--backend cpu --stats --threads 1 -o " + dir + "/w.png " + dir + "/whitted.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(": 0 triangles, 1 sphere, 3 lights (2 point, 1 directional); backend cpu, 1 thread\n"),
            std::string::npos)
      << r.output;

  const std::string quad = "quadLight -1 2 -1 2 0 0 0 0 2 5 5 5\n";
  writeFile(dir + "/path.test", kHead + "integrator pathtracer\n" + quad + "emission 1 1 1\nsphere 0 0 0 1\n");
  r = runVkrt("--backend cpu --stats --threads 2 --spp 1 -o " + dir + "/p.png " + dir + "/path.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(": 2 triangles, 1 sphere, 2 lights (1 quad, 1 emissive sphere); backend cpu, 2 threads\n"),
            std::string::npos)
      << r.output;

  // Emission lights nothing under `direct`; the quad light alone is the light there.
  writeFile(dir + "/direct.test", kHead + "integrator direct\n" + quad + "emission 1 1 1\nsphere 0 0 0 1\n");
  r = runVkrt("--backend cpu --stats --threads 1 --spp 1 -o " + dir + "/d.png " + dir + "/direct.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(", 1 light (1 quad); backend cpu"), std::string::npos) << r.output;

  // The Whitted model ignores the quad light: no light at all.
  writeFile(dir + "/ignored.test", kHead + quad + "ambient 1 1 1\nsphere 0 0 0 1\n");
  r = runVkrt("--backend cpu --stats --threads 1 -o " + dir + "/i.png " + dir + "/ignored.test");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(", 0 lights; backend cpu"), std::string::npos) << r.output;
}

// --compare prints its summary; each backend's --stats breakdown only with --stats.
TEST(CompareOutput, BreakdownsOnlyWithStats) {
  VKRT_REQUIRE_GPU(context);
  const std::string scene = sourcePath("scenes/spheres.test");
  RunResult plain = runVkrt("--compare " + scene);
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_NE(plain.output.find("vulkan vs cpu:"), std::string::npos) << plain.output;
  EXPECT_EQ(occurrences(plain.output, "\n  parse "), 0u) << plain.output;
  EXPECT_EQ(occurrences(plain.output, " maxdepth "), 0u) << plain.output;
  RunResult stats = runVkrt("--compare --stats " + scene);
  ASSERT_EQ(stats.exitCode, 0) << stats.output;
  EXPECT_EQ(occurrences(stats.output, "\n  parse "), 2u) << stats.output;
  EXPECT_NE(stats.output.find("vulkan vs cpu:"), std::string::npos) << stats.output;
}

// One batch merged is "1 batch", of "1 sample per pixel".
TEST(CountsInMessages, MergeOfOneBatch) {
  std::string dir = freshDir("warnings/merge");
  RadianceImage a(3, 2);
  for (float& v : a.rgb) v = 0.25f;
  a.text.emplace_back(kSamplesKeyword, formatSampleRecord({{{1, 0, 1}}, 2.0}));
  writePfmAtomic(a, dir + "/a.pfm");
  RunResult r = runVkrt("merge -o " + dir + "/mean.pfm " + dir + "/a.pfm");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("vkrt: averaged 1 batch (1 sample per pixel) into "), std::string::npos) << r.output;
}

// A difference of one pixel: "1 pixel", in the report and in the failure.
TEST(CountsInMessages, OnePixelDiffers) {
  std::string dir = freshDir("warnings/diff");
  Image a = gradient(4, 3), b = gradient(4, 3);
  b.pixel(1, 1)[0] = static_cast<std::uint8_t>(b.pixel(1, 1)[0] + 9);
  writePngAtomic(a, dir + "/a.png");
  writePngAtomic(b, dir + "/b.png");
  RunResult r = runVkrt("diff " + dir + "/a.png " + dir + "/b.png");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  EXPECT_NE(r.output.find("  differing   1 pixel ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  over 2/255  1 pixel ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  over 1/255  1 pixel ("), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAIL: 1 pixel differs (no threshold given"), std::string::npos) << r.output;
  r = runVkrt("diff --max-pixels-over 2:0 " + dir + "/a.png " + dir + "/b.png");
  EXPECT_NE(r.output.find("FAIL: 1 pixel (8.333%) differs by more than 2/255"), std::string::npos) << r.output;
}
