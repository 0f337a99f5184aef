// Numerical robustness (doc/robustness.md, "Numerical robustness"): the same picture at every scale and
// place (metamorphic: a scene against itself scaled or moved), watertight triangles,
// degenerate primitives, and the edge cases of the shading equation, on both backends.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "cpu/path_reference.h"
#include "gpu/vulkan_path_renderer.h"
#include "compare/image_diff.h"
#include "image/image.h"
#include "image/pfm.h"
#include "path_scenes.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "scene/ray_offset.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;
namespace fs = std::filesystem;

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
// light (lights follow the transform; doc/scene-format.md, "Conventions"). Attenuation is constant, so the
// picture is the same at every scale.
std::string stiffScene(double k, dvec3 offset, bool viaFile, const std::string& extra = "") {
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
  return s + extra;
}

struct Variant {
  const char* name;
  double k;
  double offset;
  bool viaFile;
  const char* extra = "";   // lines added at the end (in the scene's own units)
};
void PrintTo(const Variant& v, std::ostream* os) { *os << v.name; }

// Issue tolerance: at most 0.1% of pixels off by more than 2/255.
long long scaleTolerance(const Image& img) { return img.width * img.height / 1000; }

class ScaleInvariance : public ::testing::TestWithParam<Variant> {};

}  // namespace

TEST_P(ScaleInvariance, CpuPictureIsTheSame) {
  const Variant v = GetParam();
  Image base = renderText(stiffScene(1, dvec3(0), false));
  Image moved = renderText(stiffScene(v.k, dvec3(v.offset), v.viaFile, v.extra));
  EXPECT_TRUE(imagesClose(std::string("scale-cpu/") + v.name, moved, base, 2, scaleTolerance(base)));
}

TEST_P(ScaleInvariance, VulkanPictureIsTheSame) {
  VKRT_REQUIRE_GPU(context);
  const Variant v = GetParam();
  Image base = renderGpu(parseScene(stiffScene(1, dvec3(0), false), "base.test"));
  Image moved = renderGpu(parseScene(stiffScene(v.k, dvec3(v.offset), v.viaFile, v.extra), "moved.test"));
  EXPECT_TRUE(imagesClose(std::string("scale-gpu/") + v.name, moved, base, 2, scaleTolerance(base)));
  // And the two backends agree on the moved scene too.
  Image cpu = renderText(stiffScene(v.k, dvec3(v.offset), v.viaFile, v.extra));
  EXPECT_TRUE(imagesClose(std::string("scale-gpu-vs-cpu/") + v.name, moved, cpu, 2, scaleTolerance(base)));
}

INSTANTIATE_TEST_SUITE_P(Stiff, ScaleInvariance,
                         ::testing::Values(Variant{"milli", 1e-3, 0, false}, Variant{"times1e4", 1e4, 0, false},
                                           Variant{"moved1e4", 1, 1e4, false}, Variant{"milliInFile", 1e-3, 0, true},
                                           Variant{"times1e4InFile", 1e4, 0, true},
                                           Variant{"milliMoved", 1e-3, 10, false},
                                           // Beyond float32's range of squares, and its extremes.
                                           Variant{"times1e20", 1e20, 0, false}, Variant{"times1em30", 1e-30, 0, false},
                                           Variant{"times1e30", 1e30, 0, false}, Variant{"times1em30InFile", 1e-30, 0, true},
                                           Variant{"times1em150", 1e-150, 0, false}, Variant{"times1e150", 1e150, 0, false},
                                           Variant{"times1e20InFile", 1e20, 0, true},
                                           Variant{"times1e20Moved", 1e20, 1e25, false},
                                           Variant{"times1em30Moved", 1e-30, 1e-25, false},
                                           // One far object widens the scene's box; the picture stays.
                                           Variant{"farSphere1e7", 1, 0, false, "sphere 1e7 0 0 1\n"},
                                           Variant{"farSphere1e8", 1, 0, false, "sphere 1e8 0 0 1\n"},
                                           Variant{"farSpheres1e15", 1, 0, false,
                                                   "sphere 1e15 0 0 1\nsphere 0 -1e15 0 1\nsphere 0 0 -1e15 1\n"},
                                           Variant{"farSphere1e7Milli", 1e-3, 0, false, "sphere 1e4 0 0 1e-3\n"}),
                         [](const auto& p) { return std::string(p.param.name); });

// A sphere's radius far from 1, with its transform making up for it (`scale 1e-10` around a
// sphere of radius 1e10, `scale 1e20` around one of 1e-20): the same sphere, the same picture.
TEST(SphereRadius, FarFromOneAgainstItsTransformGivesTheSamePicture) {
  const std::string base = stiffScene(1, dvec3(0), false);
  const std::string plain = "sphere 0 1 0 1\n";
  ASSERT_NE(base.find(plain), std::string::npos);
  Context* context = gpuContextOrSkip();
  const Image cpuBase = renderText(base);
  const Image gpuBase = context ? renderGpu(parseScene(base, "base.test")) : Image{};
  const std::pair<const char*, const char*> variants[] = {
      {"1e10", "pushTransform\nscale 1e-10 1e-10 1e-10\nsphere 0 1e10 0 1e10\npopTransform\n"},
      {"1e-20", "pushTransform\nscale 1e20 1e20 1e20\nsphere 0 1e-20 0 1e-20\npopTransform\n"},
      {"1e30", "pushTransform\nscale 1e-30 1e-30 1e-30\nsphere 0 1e30 0 1e30\npopTransform\n"}};
  for (const auto& [name, variant] : variants) {
    std::string text = base;
    text.replace(text.find(plain), plain.size(), variant);
    EXPECT_TRUE(imagesClose(std::string("radius-cpu/") + name, renderText(text), cpuBase, 2, scaleTolerance(cpuBase)));
    if (context) {
      EXPECT_TRUE(imagesClose(std::string("radius-gpu/") + name, renderGpu(parseScene(text, "radius.test")), gpuBase,
                              2, scaleTolerance(gpuBase)));
    }
  }
}

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

// The edge cases of doc/scene-format.md, "Shading" and the camera, each rendered by both backends, which must
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

namespace {

// The scene with every length multiplied by k and then moved by `offset` (point lights'
// attenuation made up for, so that the picture is the same).
SceneDesc scaledScene(SceneDesc s, double k, const dvec3& offset) {
  const dmat4 m = glm::scale(glm::translate(dmat4(1.0), offset), dvec3(k));
  auto at = [&](const dvec3& p) { return p * k + offset; };
  for (Triangle& t : s.triangles)
    for (dvec3& p : t.p) p = at(p);
  for (Sphere& sp : s.spheres) {
    sp.worldFromObject = m * sp.worldFromObject;
    sp.objectFromWorld = glm::inverse(sp.worldFromObject);
  }
  for (QuadLight& q : s.quadLights) {
    q.a = at(q.a);
    q.ab *= k;
    q.ac *= k;
  }
  for (Light& l : s.lights) {
    if (l.type == LightType::Point) l.vec = at(l.vec);
    l.attenuation = dvec3(l.attenuation.x, l.attenuation.y / k, l.attenuation.z / k / k);
  }
  s.camera.from = at(s.camera.from);
  s.camera.at = at(s.camera.at);
  return s;
}

}  // namespace

// The path tracer with next-event estimation of a quad light and of emissive triangles and
// ellipsoids (areas, densities and pick weights in the float32 frame's units): the same
// picture at every scale and place, on both backends. Tolerance: 30 of the 1024 pixels more
// than 2/255 off (as between the backends: pixel centres on the diagonals see two walls' edge
// exactly, and the secondary-ray offsets scale by whole decades, not exactly by 2^70).
TEST(PathScaleInvariance, QuadLightAndEmittersAtEveryScale) {
  // The box with its quad light, and the emissive ellipsoid and triangle of the other box.
  SceneDesc base = cornellLikeBox(32, 3);
  const SceneDesc emitters = emissiveSurfacesBox(32, 3);
  base.materials.insert(base.materials.end(), emitters.materials.begin() + static_cast<long>(base.materials.size()),
                        emitters.materials.end());
  base.spheres = emitters.spheres;
  base.triangles.push_back(emitters.triangles.back());
  base.path.nextEvent = NextEvent::Mis;
  PathOptions cpu;
  cpu.seed = 17;
  cpu.sampleCount = 4;
  VulkanPathOptions gpu;
  gpu.seed = 17;
  gpu.sampleCount = 4;
  Context* context = gpuContextOrSkip();
  auto render = [&](const SceneDesc& s, bool onGpu) {
    RayCounts counts;
    RadianceImage r = onGpu ? renderVulkanPath(*context, flatten(s), gpu, &counts, nullptr)
                            : renderPathReference(s, buildBvh(s), cpu, &counts);
    EXPECT_EQ(counts.nonFinite, 0u);
    Image img(r.width, r.height);
    for (std::size_t i = 0; i < r.rgb.size(); ++i) img.rgb[i] = radianceToByte(r.rgb[i]);
    return img;
  };
  for (bool onGpu : {false, true}) {
    if (onGpu && !context) break;
    const Image expected = render(base, onGpu);
    long long lit = 0;
    for (std::uint8_t b : expected.rgb) lit += b != 0;
    ASSERT_GT(lit, 100);
    const std::pair<const char*, SceneDesc> variants[] = {
        {"2^70", scaledScene(base, 0x1p70, dvec3(0.0))},
        {"1e20", scaledScene(base, 1e20, dvec3(0.0))},
        {"1e-30", scaledScene(base, 1e-30, dvec3(0.0))},
        {"1e-30moved", scaledScene(base, 1e-30, dvec3(3e-30, -1e-29, 2e-30))},
        {"1e30", scaledScene(base, 1e30, dvec3(0.0))}};
    for (const auto& [name, scene] : variants) {
      const Image actual = render(scene, onGpu);
      const std::string label = std::string(onGpu ? "path-scale-gpu/" : "path-scale-cpu/") + name;
      EXPECT_TRUE(imagesClose(label, actual, expected, 2, 30));
    }
  }
}

// A point light's attenuation c0 + c1 r + c2 r^2 at every scale (the scene's c1 / k and
// c2 / k^2 with it): the float32 frame's own units must not change the light.
TEST(AttenuationScaleInvariance, SameLightAtEveryScale) {
  const SceneDesc base = parseScene(
      litRoom("camera 0 1 6 0 0 0 0 1 0 45\nattenuation 0.5 0.3 0.2\ndiffuse 0.7 0.7 0.7\nspecular 0.2 0.2 0.2\n"
              "shininess 20"),
      "attenuation.test");
  Context* context = gpuContextOrSkip();
  const Image cpuBase = renderScene(base);
  const Image gpuBase = context ? renderGpu(base) : Image{};
  for (double k : {1e20, 0x1p-90, 1e-30, 1e30}) {
    const SceneDesc scaled = scaledScene(base, k, dvec3(0.5 * k));
    EXPECT_TRUE(imagesClose("attenuation-cpu/" + num(k), renderScene(scaled), cpuBase, 2, 3));
    if (context) {
      EXPECT_TRUE(imagesClose("attenuation-gpu/" + num(k), renderGpu(scaled), gpuBase, 2, 3));
    }
  }
}

// Directions stated with tiny or vast vectors (a rotation axis, the camera's up vector and
// its look-at point, a directional light, vertex normals) mean the same direction: the same
// picture as with vectors of ordinary length, on both backends. A vector is multiplied by
// each factor; its length's square underflows or overflows double precision.
TEST(TinyVectors, DirectionsOfAnyLengthGiveTheSamePicture) {
  auto scene = [](double f) {
    auto v = [f](double x, double y, double z) { return num(x * f) + " " + num(y * f) + " " + num(z * f); };
    // The camera at the origin (so that a look-at point 1e-200 away is representable), the
    // rest moved in front of it.
    std::string s = "size 48 36\ncamera 0 0 0 " + v(0, -1, -6) + " " + v(0, 1, 0) + " 45\ntranslate 0 -1 -6\n";
    s += "directional " + v(1, 1, 2) + " 0.6 0.6 0.6\npoint 0 3 3 0.5 0.5 0.5\n";
    s += "diffuse 0.5 0.4 0.3\nspecular 0.3 0.3 0.3\nshininess 20\n";
    s += "pushTransform\nrotate " + v(1, 2, 3) + " 40\nscale 1.5 0.6 1\nsphere 0 0 0 1\npopTransform\n";
    s += "vertexnormal -3 -1 -3 " + v(0, 1, 0.3) + "\nvertexnormal 3 -1 -3 " + v(0.2, 1, 0) +
         "\nvertexnormal 0 -1 3 " + v(-0.2, 1, 0) + "\ntrinormal 0 1 2\n";
    return s;
  };
  const SceneDesc base = parseScene(scene(1.0), "base.test");
  Context* context = gpuContextOrSkip();
  const Image cpuBase = renderScene(base);
  long long lit = 0;
  for (std::uint8_t b : cpuBase.rgb) lit += b != 0;
  ASSERT_GT(lit, 1000);
  const Image gpuBase = context ? renderGpu(base) : Image{};
  for (double f : {1e-200, 1e-160, 1e200, 1e300}) {
    const SceneDesc s = parseScene(scene(f), "tiny.test");
    EXPECT_TRUE(imagesClose("tiny-vectors-cpu/" + num(f), renderScene(s), cpuBase, 1, 3));
    if (context) {
      EXPECT_TRUE(imagesClose("tiny-vectors-gpu/" + num(f), renderGpu(s), gpuBase, 1, 3));
    }
  }
}

// A triangle far smaller than anything it is near (1e-20 to 1e-100 across, hidden at the
// centre of a unit sphere, in three planes through it) changes no pixel: rays that pass far from it never
// "hit" it through rounding (the CPU reference computes edge functions from the edges).
TEST(TinyVectors, ATinyTriangleInsideASphereChangesNothing) {
  const std::string base = "size 80 60\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 3 3 3 1 1 1\ndirectional 0 0 1 .3 .3 .3\n"
                           "diffuse 0.5 0.5 0.5\nspecular .3 .3 .3\nshininess 20\nsphere 0 0 0 1\n";
  Context* context = gpuContextOrSkip();
  const Image cpuBase = renderText(base);
  const Image gpuBase = context ? renderGpu(parseScene(base, "base.test")) : Image{};
  for (double size : {1e-20, 1e-9, 1e-100})
    for (const char* turn : {"", "rotate 0 1 0 90\n", "rotate 1 2 3 30\n"}) {   // about the centre
      const std::string axis = turn[0] == 0 ? "xy" : turn[7] == '0' ? "yz" : "tilted";
      std::string text = base + turn + "vertex 0 0 0\nvertex " + num(size) + " 0 0\nvertex 0 " + num(size) +
                         " 0\ntri 0 1 2\n";
      EXPECT_TRUE(imagesClose("tiny-triangle-cpu/" + num(size) + axis, renderText(text), cpuBase, 0, 0));
      if (context) {
        EXPECT_TRUE(imagesClose("tiny-triangle-gpu/" + num(size) + axis, renderGpu(parseScene(text, "tiny.test")),
                                gpuBase, 0, 0));
      }
    }
}

// ---- What reaches a file is finite ------------------------------------------------------------

namespace {

// Every channel of the PFM at `path` is finite; returns the largest in absolute value.
float largestFiniteChannel(const std::string& path) {
  const RadianceImage img = readPfm(path);
  float largest = 0.0f;
  for (float c : img.rgb) {
    EXPECT_TRUE(std::isfinite(c)) << path;
    if (std::isfinite(c)) largest = std::max(largest, std::abs(c));
  }
  return largest;
}

std::vector<std::string> backendsHere() {
  std::vector<std::string> b = {"cpu"};
  if (gpuContextOrSkip()) b.push_back("vulkan");
  return b;
}

}  // namespace

// A colour, light or radiance beyond float32 (the Vulkan backend's precision) renders as the
// largest float, with a warning at its line (an error with --strict), on both backends; the
// PFM holds no infinity.
TEST(FiniteOutput, ValuesBeyondFloatAreClampedWithAWarningAtTheirLine) {
  const std::string dir = freshDir("finite/beyond-float");
  const std::pair<std::string, std::string> cases[] = {
      {"emission 1e39 0 0", "'emission' argument 1 '1e39'"},
      {"ambient 0 -1e300 0", "'ambient' argument 2 '-1e300'"},
      {"point 0 0 5 1e300 1 1", "'point' argument 4 '1e300'"},
      {"directional 0 0 1 1 1 1e39", "'directional' argument 6 '1e39'"}};
  for (const std::string& backend : backendsHere())
    for (const auto& [line, quoted] : cases) {
      writeFile(dir + "/s.test", "size 20 10\ncamera 0 0 5 0 0 0 0 1 0 45\n" + line + "\ndiffuse 0.5 0.5 0.5\n"
                                 "sphere 0 0 0 1\n");
      const std::string message = quoted + " is beyond the largest float32 value (3.4028235e38)";
      RunResult r = runVkrt("--backend " + backend + " -o " + dir + "/o.pfm " + dir + "/s.test");
      EXPECT_EQ(r.exitCode, 0) << r.output;
      EXPECT_NE(r.output.find(dir + "/s.test:3: warning: " + message), std::string::npos) << r.output;
      EXPECT_EQ(r.output.find("NaN or infinite"), std::string::npos) << r.output;
      if (fileExists(dir + "/o.pfm")) {
        EXPECT_GT(largestFiniteChannel(dir + "/o.pfm"), 0.1f) << line;
      }
      fs::remove(dir + "/o.pfm");
      RunResult strict = runVkrt("--strict --backend " + backend + " -o " + dir + "/o.pfm " + dir + "/s.test");
      EXPECT_EQ(strict.exitCode, 2) << strict.output;
      EXPECT_NE(strict.output.find(dir + "/s.test:3: error: " + message), std::string::npos) << strict.output;
      EXPECT_FALSE(fileExists(dir + "/o.pfm"));
    }
}

// Values within float32 whose sum is beyond it: both backends count the pixels (a warning; an
// error with --strict) and write the largest float, never an infinity.
TEST(FiniteOutput, SumsBeyondFloatAreCountedAndWrittenFinite) {
  const std::string dir = freshDir("finite/sums");
  writeFile(dir + "/s.test", "size 20 10\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 3e38 3e38 3e38\n"
                             "emission 3e38 0 0\nsphere 0 0 0 1\n");
  for (const std::string& backend : backendsHere()) {
    RunResult r = runVkrt("--backend " + backend + " -o " + dir + "/o.pfm " + dir + "/s.test");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("vkrt: warning: 16 pixels had a NaN or infinite colour"), std::string::npos)
        << backend << ": " << r.output;
    EXPECT_EQ(largestFiniteChannel(dir + "/o.pfm"), std::numeric_limits<float>::max()) << backend;
    RunResult strict = runVkrt("--strict --backend " + backend + " -o " + dir + "/s.pfm " + dir + "/s.test");
    EXPECT_EQ(strict.exitCode, 2) << strict.output;
  }
}

// The path integrators with BRDF sampling at accepted extremes (Phong shininess 1e9 and
// beyond, GGX roughness 1e30 and 1e-15): clamped, with a warning at the line, to values that
// render finite on both backends and give the same picture as those values given directly,
// and the same on both backends (the same paths: the mean radiance within 1%). Before the
// limits of 1e7 and 1e-4, the Vulkan backend drew shininess 1e9 a quarter too dark and
// roughness 1e-15 as NaN pixels.
TEST(FiniteOutput, ExtremeBrdfParametersRenderFinite) {
  auto scene = [](const std::string& material, const char* nee) {
    return "size 24 18\nintegrator pathtracer\nspp 8\nmaxdepth 3\nimportancesampling brdf\nnexteventestimation " +
           std::string(nee) + "\ncamera 0 1 5 0 0 0 0 1 0 45\nquadLight -1 3 -1 0 0 2 2 0 0 5 5 5\n"
           "diffuse 0.3 0.3 0.3\nspecular 0.5 0.5 0.5\n" + material + "\nsphere 0 0 0 1\n"
           "vertex -5 -1 -5\nvertex 5 -1 -5\nvertex 5 -1 5\nvertex -5 -1 5\ntri 0 3 2\ntri 0 2 1\n";
  };
  Context* context = gpuContextOrSkip();
  const std::pair<std::string, std::string> cases[] = {{"shininess 1e20", "shininess 1e7"},
                                                       {"shininess 1e300", "shininess 1e7"},
                                                       {"shininess 1e9", "shininess 1e7"},
                                                       {"brdf ggx\nroughness 1e30", "brdf ggx\nroughness 1e4"},
                                                       {"brdf ggx\nroughness 1e-15", "brdf ggx\nroughness 1e-4"}};
  for (const auto& [extreme, limit] : cases)
    for (const char* nee : {"off", "mis"}) {
      ParsedScene parsed = parseSceneWithWarnings(scene(extreme, nee), "extreme.test");
      ASSERT_FALSE(parsed.warnings.empty()) << extreme;
      EXPECT_NE(parsed.warnings.front().message.find("clamped to 1e"), std::string::npos)
          << parsed.warnings.front().message;
      const SceneDesc& s = parsed.scene;
      const SceneDesc same = parseScene(scene(limit, nee), "limit.test");
      PathOptions cpu;
      cpu.sampleCount = 8;
      RayCounts counts;
      const RadianceImage onCpu = renderPathReference(s, buildBvh(s), cpu, &counts);
      EXPECT_EQ(counts.nonFinite, 0u) << extreme << " " << nee;
      const RadianceImage cpuSame = renderPathReference(same, buildBvh(same), cpu, nullptr);
      EXPECT_EQ(onCpu.rgb, cpuSame.rgb) << extreme << " " << nee;
      if (!context) continue;
      VulkanPathOptions gpu;
      gpu.sampleCount = 8;
      RayCounts gpuCounts;
      const RadianceImage onGpu = renderVulkanPath(*context, flatten(s), gpu, &gpuCounts, nullptr);
      EXPECT_EQ(gpuCounts.nonFinite, 0u) << extreme << " " << nee;
      EXPECT_NEAR(imageMean(onGpu), imageMean(onCpu), 0.01 * imageMean(onCpu)) << extreme << " " << nee;
    }
}

// A point light (constant attenuation) so far away that its rays are parallel: the picture of
// a directional light along the same direction, on both backends, however far (its distance
// squared beyond float32, or beyond double).
TEST(FarPointLight, IsTheDirectionalLightOfItsDirection) {
  const std::string rest = "diffuse 0.5 0.4 0.3\nspecular 0.3 0.3 0.3\nshininess 20\nsphere 0 0 0 1\n"
                           "sphere 1.5 0.3 0.5 0.4\nvertex -4 -1 -4\nvertex 4 -1 -4\nvertex 4 -1 4\nvertex -4 -1 4\n"
                           "tri 0 3 2\ntri 0 2 1\n";
  const std::string camera = "size 48 36\ncamera 0 1 6 0 0 0 0 1 0 45\n";
  const std::string directional = camera + "directional 1 2 3 0.9 0.9 0.9\n" + rest;
  Context* context = gpuContextOrSkip();
  const Image cpuBase = renderText(directional);
  const Image gpuBase = context ? renderGpu(parseScene(directional, "directional.test")) : Image{};
  for (double d : {1e25, 1e100, 1e300}) {
    const std::string text = camera + "point " + num(d) + " " + num(2 * d) + " " + num(3 * d) + " 0.9 0.9 0.9\n" + rest;
    EXPECT_TRUE(imagesClose("far-light-cpu/" + num(d), renderText(text), cpuBase, 1, 3));
    if (context) {
      EXPECT_TRUE(imagesClose("far-light-gpu/" + num(d), renderGpu(parseScene(text, "far.test")), gpuBase, 1, 3));
    }
  }
}

// A look-from and look-at 2e300 apart: the difference is finite (only its square overflows),
// so the camera is valid and its basis exact; only a difference beyond double is an error
// (parse_errors_test: CameraFromAtOverflows).
TEST(TinyVectors, ACameraWhoseViewSquaredOverflowsIsValid) {
  const SceneDesc s = parseScene("size 8 6\ncamera 1e300 0 0 -1e300 0 0 0 1e300 0 45\nsphere 0 0 0 1\n", "far.test");
  EXPECT_EQ(s.camera.from.x, 1e300);
  const GpuScene g = flatten(s);
  EXPECT_EQ(g.camera.back.x, 1.0f);
  EXPECT_EQ(g.camera.back.y, 0.0f);
  EXPECT_GT(g.camera.up.y, 0.0f);
  EXPECT_LT(g.camera.right.z, 0.0f);   // right = up x back = y x x = -z
}
