// Numerical robustness (README "Numerical robustness"): the same picture at every scale and
// place (metamorphic: a scene against itself scaled or moved), watertight triangles,
// degenerate primitives, and the edge cases of the shading equation, on both backends.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "image/compare.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "scene/ray_offset.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string point(const dvec3& p) { return num(p.x) + " " + num(p.y) + " " + num(p.z); }

// Contact shadows (a sphere and an ellipsoid resting on a floor), a mirror sphere, a point
// and a directional light. Every length is multiplied by k and moved by `offset`: by hand,
// or (viaFile) through the file's own `translate` and `scale`, which also move the point
// light (lights follow the transform; SPEC section 7). Attenuation is constant, so the
// picture is the same at every scale.
std::string stiffScene(double k, dvec3 offset, bool viaFile) {
  auto at = [&](dvec3 p) { return point(viaFile ? p : p * k + offset); };
  auto len = [&](double v) { return num(viaFile ? v : v * k); };
  std::string s = "size 120 90\nmaxdepth 3\n";
  s += "camera " + point(dvec3(0, 3, 8) * k + offset) + " " + point(dvec3(0, 0.5, 0) * k + offset) + " 0 1 0 40\n";
  if (viaFile) s += "translate " + point(offset) + "\nscale " + num(k) + " " + num(k) + " " + num(k) + "\n";
  s += "directional 1 1 1 0.4 0.4 0.4\npoint " + at({2, 4, 3}) + " 0.8 0.8 0.8\n";
  s += "ambient 0.1 0.1 0.1\ndiffuse 0.6 0.6 0.6\nspecular 0.2 0.2 0.2\nshininess 30\n";
  for (dvec3 v : {dvec3(-4, 0, -4), dvec3(4, 0, -4), dvec3(4, 0, 4), dvec3(-4, 0, 4)}) s += "vertex " + at(v) + "\n";
  s += "tri 0 3 2\ntri 0 2 1\n";
  s += "sphere " + at({0, 1, 0}) + " " + len(1) + "\n";
  s += "pushTransform\ntranslate " + at({2.2, 0.5, 0}) + "\nscale " + len(1) + " " + len(0.5) + " " + len(0.5) +
       "\nsphere 0 0 0 1\npopTransform\n";
  s += "diffuse 0.1 0.1 0.3\nspecular 0.8 0.8 0.8\nsphere " + at({-2, 0.6, 1}) + " " + len(0.6) + "\n";
  return s;
}

struct Variant {
  const char* name;
  double k;
  double offset;
  bool viaFile;
};
void PrintTo(const Variant& v, std::ostream* os) { *os << v.name; }

// Issue tolerance: at most 0.1% of pixels off by more than 2/255.
long long scaleTolerance(const Image& img) { return img.width * img.height / 1000; }

class ScaleInvariance : public ::testing::TestWithParam<Variant> {};

}  // namespace

TEST_P(ScaleInvariance, CpuPictureIsTheSame) {
  const Variant v = GetParam();
  Image base = renderText(stiffScene(1, dvec3(0), false));
  Image moved = renderText(stiffScene(v.k, dvec3(v.offset), v.viaFile));
  EXPECT_TRUE(imagesClose(std::string("scale-cpu/") + v.name, moved, base, 2, scaleTolerance(base)));
}

TEST_P(ScaleInvariance, VulkanPictureIsTheSame) {
  VKRT_REQUIRE_GPU(context);
  const Variant v = GetParam();
  Image base = renderGpu(parseScene(stiffScene(1, dvec3(0), false), "base.test"));
  Image moved = renderGpu(parseScene(stiffScene(v.k, dvec3(v.offset), v.viaFile), "moved.test"));
  EXPECT_TRUE(imagesClose(std::string("scale-gpu/") + v.name, moved, base, 2, scaleTolerance(base)));
  // And the two backends agree on the moved scene too.
  Image cpu = renderText(stiffScene(v.k, dvec3(v.offset), v.viaFile));
  EXPECT_TRUE(imagesClose(std::string("scale-gpu-vs-cpu/") + v.name, moved, cpu, 2, scaleTolerance(base)));
}

INSTANTIATE_TEST_SUITE_P(Stiff, ScaleInvariance,
                         ::testing::Values(Variant{"milli", 1e-3, 0, false}, Variant{"times1e4", 1e4, 0, false},
                                           Variant{"moved1e4", 1, 1e4, false}, Variant{"milliInFile", 1e-3, 0, true},
                                           Variant{"times1e4InFile", 1e4, 0, true},
                                           Variant{"milliMoved", 1e-3, 10, false}),
                         [](const auto& p) { return std::string(p.param.name); });

// A fan of 1000 thin triangles around the point the centre pixel looks at, filling the view,
// emitting white: a ray that slipped between two of them would leave a black pixel. Flat and
// tilted, so that edges meet pixel centres exactly (axis-aligned edges, the shared vertex) and
// at every angle.
std::string fanScene(const std::string& transform) {
  std::string s = "size 101 101\ncamera 0 0 1 0 0 0 0 1 0 90\nambient 0 0 0\nemission 1 1 1\n" + transform +
                  "\nvertex 0 0 0\n";
  const int n = 1000;
  for (int i = 0; i < n; ++i) {
    double a = 2.0 * M_PI * i / n, x = 10.0 * std::cos(a), y = 10.0 * std::sin(a);
    if (i % (n / 4) == 0) {   // exactly on the axes
      x = i == 0 ? 10 : i == n / 2 ? -10 : 0;
      y = i == n / 4 ? 10 : i == 3 * n / 4 ? -10 : 0;
    }
    s += "vertex " + num(x) + " " + num(y) + " 0\n";
  }
  for (int i = 0; i < n; ++i) s += "tri 0 " + std::to_string(1 + i) + " " + std::to_string(1 + (i + 1) % n) + "\n";
  return s;
}

TEST(Watertight, NoRaySlipsBetweenTrianglesThatShareAnEdge) {
  Context* context = gpuContextOrSkip();
  for (const char* transform : {"", "rotate 1 2 3 17", "rotate 0 0 1 0.05"}) {
    SceneDesc scene = parseScene(fanScene(transform), "fan.test");
    std::vector<std::pair<const char*, Image>> images = {{"cpu", renderScene(scene)}};
    if (context) images.emplace_back("vulkan", renderGpu(scene));
    for (auto& [backend, img] : images) {
      long long black = 0;
      for (std::size_t i = 0; i < img.rgb.size(); i += 3) black += img.rgb[i] != 255;
      EXPECT_EQ(black, 0) << backend << ", transform '" << transform << "': rays slipped through shared edges";
    }
  }
}

TEST(Degenerate, ZeroAreaTrianglesAndPointSpheresAreNeverHit) {
  std::string s = "size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\ndirectional 0 0 1 1 1 1\nambient 0.5 0.5 0.5\n"
                  "vertex -1 -1 0\nvertex 1 1 0\nvertex 2 2 0\nvertex 1 -1 0\nvertex 1 -1 0\n"
                  "tri 0 0 1\ntri 0 1 2\ntri 3 4 0\ntri 1 1 1\n"   // repeated indices, collinear, a repeated point
                  "sphere 0 0 0 0\n";   // (a sphere under a singular transform is a parse error)
  SceneDesc scene = parseScene(s, "degenerate.test");
  EXPECT_TRUE(buildBvh(scene).primRefs.empty());
  Image cpu = renderScene(scene);   // (renderScene also fails on NaN)
  for (std::uint8_t b : cpu.rgb) ASSERT_EQ(b, 0);
  Context* context = gpuContextOrSkip();
  if (!context) return;
  Image gpu = renderGpu(scene);
  for (std::uint8_t b : gpu.rgb) ASSERT_EQ(b, 0);
}

// The edge cases of SPEC section 5 and the camera, each rendered by both backends, which must
// agree (float32 against double: the same flip allowance as the other GPU tests) and produce
// no NaN or infinity (the helpers check).
struct EdgeCase {
  const char* name;
  std::string text;
};
void PrintTo(const EdgeCase& c, std::ostream* os) { *os << c.name; }

class ShadingEdgeCase : public ::testing::TestWithParam<EdgeCase> {};

std::string litRoom(const std::string& materialAndCamera) {
  return "size 48 36\n" + materialAndCamera +
         "\npoint 0 2 3 1 1 1\ndirectional 0 1 1 0.3 0.3 0.3\n"
         "vertex -4 -1 -4\nvertex 4 -1 -4\nvertex 4 -1 4\nvertex -4 -1 4\ntri 0 3 2\ntri 0 2 1\n"
         "sphere 0 0 0 1\nsphere 1.5 0 -1 0.5\n";
}

TEST_P(ShadingEdgeCase, BackendsAgree) {
  SceneDesc scene = parseScene(GetParam().text, std::string(GetParam().name) + ".test");
  Image cpu = renderScene(scene);
  long long lit = 0;
  for (std::uint8_t b : cpu.rgb) lit += b != 0;
  EXPECT_GT(lit, 0) << "the scene should show something";
  VKRT_REQUIRE_GPU(context);
  Image gpu = renderGpu(scene);
  EXPECT_TRUE(imagesClose(std::string("edge-case/") + GetParam().name, gpu, cpu, 2,
                          std::max<long long>(3, cpu.width * cpu.height / 1000)));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ShadingEdgeCase,
    ::testing::Values(
        EdgeCase{"shininess0", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nspecular 0.5 0.5 0.5\nshininess 0")},
        EdgeCase{"shininess1e5", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nspecular 0.5 0.5 0.5\nshininess 100000")},
        EdgeCase{"tinyAttenuation", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nattenuation 0 0 1e-30\ndiffuse 0.2 0 0")},
        EdgeCase{"hugeAttenuation", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nattenuation 1e30 1e30 1e30\nambient 0.1 0 0")},
        EdgeCase{"maxdepth0", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nmaxdepth 0\nspecular 0.9 0.9 0.9")},
        EdgeCase{"maxdepth1", litRoom("camera 0 1 6 0 0 0 0 1 0 45\nmaxdepth 1\nspecular 0.9 0.9 0.9")},
        EdgeCase{"upNearlyParallel", litRoom("camera 0 6 0.001 0 0 0 0 1 0 45\ndiffuse 0.5 0.5 0.5")},
        EdgeCase{"wide", "size 600 3\ncamera 0 0 6 0 0 0 0 1 0 10\ndirectional 0 0 1 1 1 1\ndiffuse 1 0 0\n"
                         "sphere 0 0 0 1\nsphere 3 0 0 1\n"},
        EdgeCase{"tall", "size 3 600\ncamera 0 0 6 0 0 0 0 1 0 60\ndirectional 0 0 1 1 1 1\ndiffuse 1 0 0\n"
                         "sphere 0 0 0 1\nsphere 0 1.8 0 0.5\n"},
        EdgeCase{"cameraInsideSphere", "size 32 24\ncamera 0 0 0 0 0 -1 0 1 0 90\npoint 0 0 0 1 1 1\n"
                                       "diffuse 0.5 0.5 0.5\nsphere 0 0 0 5\nsphere 0 0 -3 0.5\n"}),
    [](const auto& p) { return std::string(p.param.name); });

// maxdepth 1000 between two perfect mirrors facing each other: every chain is followed to
// the end (the exactness cut-off cannot stop a path of weight 1), and ends.
TEST(ShadingEdgeCases, MaxDepth1000BetweenPerfectMirrorsEnds) {
  std::string s = "size 16 12\ncamera 0 -0.9 0 0 1 0.05 0 0 1 30\nmaxdepth 1000\npoint 0 0 0.5 0.3 0.3 0.3\n"
                  "ambient 0.001 0.001 0.001\nspecular 1 1 1\n"
                  "vertex -50 -1 -50\nvertex 50 -1 -50\nvertex 50 -1 50\nvertex -50 -1 50\n"
                  "tri 0 1 2\ntri 0 2 3\npushTransform\ntranslate 0 2 0\ntri 0 2 1\ntri 0 3 2\npopTransform\n";
  SceneDesc scene = parseScene(s, "mirrors.test");
  Image cpu = renderScene(scene);
  VKRT_REQUIRE_GPU(context);
  VulkanTimings timings;
  Image gpu = renderGpu(scene, 0, &timings);
  EXPECT_TRUE(imagesClose("edge-case/maxdepth1000", gpu, cpu, 2, 3));
}
