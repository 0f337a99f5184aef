// The views (vkrt --view NAME, render/techniques.cpp): the normals view against a closed form
// (an ellipsoid and a triangle, with their normals computed here from the camera of
// doc/scene-format.md), against itself where lights, materials and the integrator change
// (they must not change it), both backends against each other on the course scenes, and
// the command line's checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

#include "image/encode.h"
#include "image/image_read.h"
#include "render/progress.h"
#include "render/render.h"
#include "support/scene_generator.h"
#include "support/test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

RadianceImage renderView(const std::string& scenePath, Backend backend, const std::string& view = "normals") {
  return renderFileQuietly(scenePath, [&](RenderRequest& r) {
    r.backend = backend;
    r.view = view;
  });
}

// An ellipsoid (a sphere under a translation and a non-uniform scale) in front of a triangle,
// 64x48, camera at (0, 0, 5) looking down -z with fovy 30.
constexpr int kWidth = 64, kHeight = 48;
constexpr double kFovy = 30;
const dvec3 kEye(0, 0, 5), kCentre(0.5, 0, 0), kAxes(1, 0.6, 1.5);
const char* const kEllipsoidScene = R"(size 64 48
camera 0 0 5 0 0 0 0 1 0 30
point 1 1 4 1 1 1
diffuse 0.5 0.2 0.1
vertex -3 -3 -2
vertex 3 -3 -2
vertex 0 3 -2
tri 0 1 2
pushTransform
translate 0.5 0 0
scale 1 0.6 1.5
sphere 0 0 0 1
popTransform
)";

// The normals view's colour of pixel (x, y), worked out here; nothing when the pixel's ray
// passes within `margin` of an outline (where float and double may take different sides).
std::optional<dvec3> expectedNormalColour(int x, int y, double margin) {
  // doc/scene-format.md, "Camera": w from the look-at point to the eye, u = up x w, v = w x u.
  const dvec3 w(0, 0, 1), u(1, 0, 0), v(0, 1, 0);
  const double ty = std::tan(kFovy * M_PI / 360.0), tx = ty * kWidth / kHeight;
  const double a = tx * (x + 0.5 - kWidth / 2.0) / (kWidth / 2.0);
  const double b = ty * (kHeight / 2.0 - (y + 0.5)) / (kHeight / 2.0);
  const dvec3 d = glm::normalize(a * u + b * v - w);
  // The ellipsoid: |(o + t d - c) / axes| = 1.
  const dvec3 o = (kEye - kCentre) / kAxes, dd = d / kAxes;
  const double qa = glm::dot(dd, dd), qb = 2 * glm::dot(o, dd), qc = glm::dot(o, o) - 1;
  const double disc = qb * qb - 4 * qa * qc;
  if (std::abs(disc) < margin * qb * qb) return std::nullopt;
  if (disc > 0) {
    const double t = (-qb - std::sqrt(disc)) / (2 * qa);
    const dvec3 p = kEye + t * d;
    return glm::normalize((p - kCentre) / (kAxes * kAxes)) * 0.5 + 0.5;
  }
  // The triangle in the plane z = -2, counter-clockwise seen from the eye: normal +z.
  const double t = (-2 - kEye.z) / d.z;
  const dvec3 p = kEye + t * d;
  const dvec3 corner[3] = {{-3, -3, -2}, {3, -3, -2}, {0, 3, -2}};
  double least = 1e300;
  bool inside = true;
  for (int i = 0; i < 3; ++i) {
    const dvec3 e = corner[(i + 1) % 3] - corner[i], q = p - corner[i];
    const double side = (e.x * q.y - e.y * q.x) / glm::length(e);   // distance, positive inside
    least = std::min(least, std::abs(side));
    inside = inside && side > 0;
  }
  if (least < margin * 40) return std::nullopt;
  return inside ? dvec3(0.5, 0.5, 1.0) : dvec3(0.0);
}

void expectClosedForm(Backend backend, double tolerance) {
  const std::string path = freshDir("views/closed-form") + "/ellipsoid.test";
  writeFile(path, kEllipsoidScene);
  const RadianceImage image = renderView(path, backend);
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  int checked = 0, ellipsoid = 0, triangle = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::optional<dvec3> expected = expectedNormalColour(x, y, 1e-3);
      if (!expected) continue;
      ++checked;
      if (expected->z == 1.0 && expected->x == 0.5) ++triangle;
      else if (*expected != dvec3(0.0)) ++ellipsoid;
      const std::size_t at = 3 * (static_cast<std::size_t>(y) * kWidth + x);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.rgb[at + c], (*expected)[c], tolerance) << "pixel " << x << "," << y << " channel " << c;
    }
  // Most pixels are checked, and the picture has all three kinds.
  EXPECT_GT(checked, kWidth * kHeight * 9 / 10);
  EXPECT_GT(ellipsoid, 300);
  EXPECT_GT(triangle, 300);
}

TEST(NormalsView, ClosedFormCpu) { expectClosedForm(Backend::Cpu, 1e-6); }

TEST(NormalsView, ClosedFormVulkan) {
  if (!gpuContextOrSkip()) return;
  expectClosedForm(Backend::Vulkan, 2e-5);
}

// The scene without its lights, materials and mirrors, and under the path tracer: the same
// view, bit for bit, on each backend.
std::string withoutShading(const std::string& text) {
  std::istringstream in(text);
  std::string out = "integrator pathtracer\nspp 3\n", line;
  const std::regex shading(R"(^\s*(point|directional|attenuation|ambient|diffuse|specular|shininess|emission|maxdepth)\b)");
  while (std::getline(in, line))
    if (!std::regex_search(line, shading)) out += line + "\n";
  return out;
}

void expectShadingIgnored(Backend backend) {
  const std::string dir = freshDir(std::string("views/shading-") + (backend == Backend::Cpu ? "cpu" : "vulkan"));
  for (std::uint64_t seed : {3u, 11u, 26u}) {
    const std::string text = difftest::generateScene(seed);
    const std::string plain = dir + "/plain.test", bare = dir + "/bare.test";
    writeFile(plain, text);
    writeFile(bare, withoutShading(text));
    const RadianceImage a = renderView(plain, backend), b = renderView(bare, backend);
    EXPECT_TRUE(sameBits(a, b)) << "seed " << seed;
    EXPECT_GT(imageMean(a), 0.01) << "seed " << seed << ": the view sees something";
  }
}

TEST(NormalsView, LightsMaterialsAndIntegratorChangeNothingCpu) { expectShadingIgnored(Backend::Cpu); }

TEST(NormalsView, LightsMaterialsAndIntegratorChangeNothingVulkan) {
  if (!gpuContextOrSkip()) return;
  expectShadingIgnored(Backend::Vulkan);
}

// A scene scaled by 3 and moved keeps its normals: the same view but where float rounding
// puts an outline's pixel on the other side (at most a few in a thousand).
TEST(NormalsView, ScaledAndMovedKeepsTheView) {
  const std::string dir = freshDir("views/scaled");
  for (std::uint64_t seed : {5u, 17u}) {
    const std::string text = difftest::generateScene(seed);
    writeFile(dir + "/a.test", text);
    writeFile(dir + "/b.test", difftest::scaledAndMoved(text, 3.0, dvec3(2, -1, 0.5)));
    const Image a = encodeImage(renderView(dir + "/a.test", Backend::Cpu), 1.0);
    const Image b = encodeImage(renderView(dir + "/b.test", Backend::Cpu), 1.0);
    EXPECT_TRUE(imagesClose("views-scaled-" + std::to_string(seed), b, a, 2, std::max(3, a.width * a.height / 300)));
  }
}

// The two backends on the course's scenes: at most 1 pixel in 1,000 more than 2/255 apart
// (an outline's pixel that float and double put on different sides).
TEST(NormalsView, BackendsAgreeOnTheCourseScenes) {
  const std::optional<std::string> dir = cse167Dir();
  if (!dir) GTEST_SKIP() << "no ../shared/cse167 (the course scenes)";
  if (!gpuContextOrSkip()) return;
  for (const char* name : {"scene1", "scene3", "scene5", "scene6", "scene7"}) {
    const std::string path = *dir + "/scenes/" + name + ".test";
    const Image cpu = encodeImage(renderView(path, Backend::Cpu), 1.0);
    const Image gpu = encodeImage(renderView(path, Backend::Vulkan), 1.0);
    EXPECT_TRUE(imagesClose(std::string("views-normals-") + name, gpu, cpu, 2,
                            std::max<long long>(3, static_cast<long long>(cpu.width) * cpu.height / 1000)));
  }
}

// Written to a file on the Vulkan backend (a view's rows stream to the encoder as the Whitted
// model's do): the bytes of the image rendered in memory.
TEST(NormalsView, StreamedFileIsTheImage) {
  if (!gpuContextOrSkip()) return;
  const std::string dir = freshDir("views/streamed");
  writeFile(dir + "/e.test", kEllipsoidScene);
  ASSERT_EQ(runVkrt("--view normals " + dir + "/e.test -o " + dir + "/n.png").exitCode, 0);
  const Image written = readImageAsBytes(dir + "/n.png");
  const Image expected = encodeImage(renderView(dir + "/e.test", Backend::Vulkan), 1.0);
  EXPECT_TRUE(imagesClose("views-streamed", written, expected, 0, 0));
}

// The command line: an unknown view names the views; a view ignores the sample options, with
// a warning; a view's image is not a piece of the scene's own render (merge refuses the two).
TEST(NormalsView, CommandLine) {
  const std::string dir = freshDir("views/cli");
  writeFile(dir + "/e.test", kEllipsoidScene);
  RunResult bad = runVkrt("--backend cpu --view normal " + dir + "/e.test -o " + dir + "/bad.png");
  EXPECT_EQ(bad.exitCode, 1);   // a usage error
  EXPECT_NE(bad.output.find("unknown view 'normal' (expected: normals"), std::string::npos) << bad.output;
  EXPECT_FALSE(fileExists(dir + "/bad.png"));

  RunResult spp = runVkrt("--backend cpu --view normals --spp 4 " + dir + "/e.test -o " + dir + "/n.png");
  EXPECT_EQ(spp.exitCode, 0) << spp.output;
  EXPECT_NE(spp.output.find("--spp does not apply to --view normals (one deterministic sample per pixel)"),
            std::string::npos)
      << spp.output;

  ASSERT_EQ(runVkrt("--backend cpu --view normals --crop 0,0,32,48 " + dir + "/e.test -o " + dir + "/left.png").exitCode,
            0);
  ASSERT_EQ(runVkrt("--backend cpu --crop 32,0,64,48 " + dir + "/e.test -o " + dir + "/right.png").exitCode, 0);
  RunResult merged = runVkrt("merge " + dir + "/left.png " + dir + "/right.png -o " + dir + "/whole.png");
  EXPECT_NE(merged.exitCode, 0) << merged.output;
  EXPECT_FALSE(fileExists(dir + "/whole.png"));
}

}  // namespace
