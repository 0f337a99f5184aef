// The path integrators on the GPU (pathtrace.comp): closed forms (analyticdirect under a
// square light, a white furnace), the invariants of a counter-based render (same seed, crops,
// suspension), and statistical agreement of the sampling strategies (doc/path-tracing.md
// section 4). The scenes are built in code. The validation layer stays silent throughout.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include <gtest/gtest.h>

#include "gpu/vulkan_path_renderer.h"
#include "image/png.h"
#include "path_scenes.h"
#include "util/ray_counts.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// ---- scenes --------------------------------------------------------------------------------

SceneDesc baseScene(int w, int h, Integrator integrator) {
  SceneDesc s;
  s.width = w;
  s.height = h;
  s.path.integrator = integrator;
  s.path.spp = 64;   // samples uniform in the pixel (a render of spp 1 would sample the centres)
  return s;
}

// A small Cornell-like box, open toward the camera: coloured diffuse walls, a Phong box and a
// GGX sphere, one quad light under the ceiling.
SceneDesc boxScene(int size) {
  SceneDesc s = baseScene(size, size, Integrator::PathTracer);
  s.camera.from = dvec3(0, 1, 3.2);
  s.camera.at = dvec3(0, 1, 0);
  s.camera.fovyDegrees = 45;
  Material wall;
  wall.ambient = dvec3(0.0);
  wall.diffuse = dvec3(0.7, 0.7, 0.7);
  std::uint32_t white = addMaterial(s, wall);
  wall.diffuse = dvec3(0.7, 0.1, 0.1);
  std::uint32_t red = addMaterial(s, wall);
  wall.diffuse = dvec3(0.1, 0.7, 0.1);
  std::uint32_t green = addMaterial(s, wall);
  Material phong = wall;
  phong.diffuse = dvec3(0.4, 0.4, 0.5);
  phong.specular = dvec3(0.3, 0.3, 0.3);
  phong.shininess = 20;
  std::uint32_t glossy = addMaterial(s, phong);
  Material ggx = wall;
  ggx.diffuse = dvec3(0.2, 0.3, 0.2);
  ggx.specular = dvec3(0.5, 0.4, 0.3);
  ggx.brdf = BrdfModel::Ggx;
  ggx.roughness = 0.3;
  std::uint32_t metal = addMaterial(s, ggx);
  // Walls facing inward: floor, ceiling, back, left, right.
  addQuad(s, dvec3(-1, 0, 1), dvec3(0, 0, -2), dvec3(2, 0, 0), white);
  addQuad(s, dvec3(-1, 2, -1), dvec3(0, 0, 2), dvec3(2, 0, 0), white);
  addQuad(s, dvec3(-1, 0, -1), dvec3(0, 2, 0), dvec3(2, 0, 0), white);
  addQuad(s, dvec3(-1, 0, 1), dvec3(0, 2, 0), dvec3(0, 0, -2), red);
  addQuad(s, dvec3(1, 0, -1), dvec3(0, 2, 0), dvec3(0, 0, 2), green);
  // A box (its top and two sides that face the camera).
  addQuad(s, dvec3(-0.6, 0.6, 0.0), dvec3(0, 0, -0.5), dvec3(0.5, 0, 0), glossy);
  addQuad(s, dvec3(-0.6, 0.0, 0.0), dvec3(0, 0.6, 0), dvec3(0.5, 0, 0), glossy);
  addQuad(s, dvec3(-0.1, 0.0, 0.0), dvec3(0, 0.6, 0), dvec3(0, 0, -0.5), glossy);
  Sphere ball;
  ball.center = dvec3(0.45, 0.35, 0.2);
  ball.radius = 0.35;
  ball.worldFromObject = dmat4(1.0);
  ball.objectFromWorld = dmat4(1.0);
  ball.material = metal;
  s.spheres.push_back(ball);
  addQuadLight(s, dvec3(-0.3, 1.99, -0.3), dvec3(0, 0, 0.6), dvec3(0.6, 0, 0), dvec3(8, 7, 6));
  return s;
}

// ---- rendering -------------------------------------------------------------------------------

RadianceImage renderPath(const SceneDesc& scene, VulkanPathOptions options = {}, RayCounts* rays = nullptr,
                         VulkanTimings* timings = nullptr) {
  Context* context = gpuContextOrSkip();
  if (!context) return {};
  int before = context->validationMessages();
  RayCounts counts;
  RadianceImage image = renderVulkanPath(*context, flatten(scene), options, &counts, timings);
  EXPECT_EQ(context->validationMessages(), before) << "the Vulkan validation layer reported problems (see stderr)";
  EXPECT_EQ(counts.nonFinite, 0u) << "the shader produced NaN or infinite samples";
  if (rays) *rays = counts;
  return image;
}

// For a look at a failure: the image as a PNG (clamped, gamma 1) in the test-output folder.
void save(const RadianceImage& r, const std::string& name) {
  Image img(r.width, r.height);
  for (std::size_t i = 0; i < r.rgb.size(); ++i) {
    float v = r.rgb[i];
    img.rgb[i] = static_cast<std::uint8_t>(v > 0.0f ? std::floor(std::min(v, 1.0f) * 255.0f) : 0.0f);
  }
  writePngAtomic(img, freshDir("gpu-path/" + name) + "/image.png");
}

// ---- statistics --------------------------------------------------------------------------------

// The two-sided tail probability P(|T| > t) of Student's t with nu degrees of freedom, by
// Simpson's rule on the density (t <= 60 is plenty here).
double studentTwoSidedTail(double t, double nu) {
  const double c = std::exp(std::lgamma((nu + 1) / 2) - std::lgamma(nu / 2)) / std::sqrt(nu * std::numbers::pi);
  auto density = [&](double x) { return c * std::pow(1 + x * x / nu, -(nu + 1) / 2); };
  const int n = 20000;
  const double h = t / n;
  double s = density(0) + density(t);
  for (int i = 1; i < n; ++i) s += density(i * h) * (i % 2 ? 4 : 2);
  return std::max(0.0, 1.0 - 2.0 * s * h / 3.0);
}

// The |t| beyond which a two-sided test of nu degrees of freedom rejects at level alpha.
double studentCritical(double alpha, double nu) {
  double lo = 0, hi = 60;
  for (int i = 0; i < 60; ++i) {
    double mid = (lo + hi) / 2;
    (studentTwoSidedTail(mid, nu) > alpha ? lo : hi) = mid;
  }
  return hi;
}

// Per-block t-tests that two images have the same expected value: in each b x b block and
// channel, the pixel differences d = A - B are independent (the generator keys each pixel
// apart) with mean 0 when both estimators are unbiased, so mean(d) / (sd(d) / sqrt(n)) follows
// Student's t with n - 1 degrees of freedom. Each test runs at the Sidak-corrected level
// 1 - (1 - familyAlpha)^(1 / tests), so that the whole family raises a false alarm with
// probability familyAlpha. Returns the failing blocks' descriptions (empty: pass).
std::vector<std::string> blockTTests(const RadianceImage& a, const RadianceImage& b, int block, double familyAlpha,
                                     int familyTests) {
  const int n = block * block;
  const double alpha = 1.0 - std::pow(1.0 - familyAlpha, 1.0 / familyTests);
  const double critical = studentCritical(alpha, n - 1);
  std::vector<std::string> failures;
  for (int by = 0; by + block <= a.height; by += block)
    for (int bx = 0; bx + block <= a.width; bx += block)
      for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0;
        for (int y = by; y < by + block; ++y)
          for (int x = bx; x < bx + block; ++x) {
            double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
            sum += d;
            sum2 += d * d;
          }
        double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
        double t = var > 0 ? mean / std::sqrt(var / n) : (mean == 0 ? 0 : INFINITY);
        if (!(std::abs(t) <= critical))
          failures.push_back("block (" + std::to_string(bx) + "," + std::to_string(by) + ") channel " +
                             std::to_string(c) + ": t = " + std::to_string(t) + " beyond " + std::to_string(critical));
      }
  return failures;
}

// ---- closed forms -------------------------------------------------------------------------------

// The form factor from a point to a parallel X x Y rectangle at height h with a corner right
// above the point (the classic closed form; e.g. Howell's catalogue, configuration B-4):
// F = 1/(2 pi) [x/sqrt(1+x^2) atan(y/sqrt(1+x^2)) + y/sqrt(1+y^2) atan(x/sqrt(1+y^2))], x = X/h, y = Y/h.
double cornerFormFactor(double width, double depth, double h) {
  double x = width / h, y = depth / h;
  double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * std::numbers::pi);
}

// A diffuse floor (y = 0) under a square light of side 2 at height h, facing down, whose corner
// or centre is above the origin; the camera looks straight down at the origin through the
// centre pixel of a 9x9 image (spp 1: the pixel centre).
SceneDesc floorUnderSquareLight(double h, bool cornerAbove, dvec3 kd, dvec3 radiance) {
  SceneDesc s = baseScene(9, 9, Integrator::AnalyticDirect);
  s.camera.from = dvec3(0, h / 2, 0);
  s.camera.at = dvec3(0, 0, 0);
  s.camera.up = dvec3(0, 0, -1);
  s.camera.fovyDegrees = 30;
  s.path.spp = 1;   // the centre pixel's ray: straight down at the origin
  Material floor;
  floor.ambient = dvec3(0.0);
  floor.diffuse = kd;
  addQuad(s, dvec3(-10, 0, 10), dvec3(0, 0, -20), dvec3(20, 0, 0), addMaterial(s, floor));
  dvec3 a = cornerAbove ? dvec3(0, h, 0) : dvec3(-1, h, -1);
  addQuadLight(s, a, dvec3(0, 0, 2), dvec3(2, 0, 0), radiance);   // cross(ac, ab) = -y: facing down
  return s;
}

// An inward-facing closed box whose every wall emits Le and reflects with albedo a (diffuse):
// the radiance everywhere inside is Le (1 + a + ... + a^D) for maxdepth D, Le / (1 - a) without
// a limit.
SceneDesc furnaceScene(double albedo, double emission) {
  SceneDesc s = baseScene(24, 24, Integrator::PathTracer);
  s.camera.from = dvec3(0.1, 0.2, 0.3);
  s.camera.at = dvec3(0.4, -0.3, -1);
  s.camera.fovyDegrees = 100;
  Material m;
  m.ambient = dvec3(0.0);
  m.diffuse = dvec3(albedo);
  m.emission = dvec3(emission);
  std::uint32_t wall = addMaterial(s, m);
  const dvec3 x(2, 0, 0), y(0, 2, 0), z(0, 0, 2), o(-1, -1, -1);
  addQuad(s, o, y, x, wall);           // back (z = -1), facing +z
  addQuad(s, o + z, x, y, wall);       // front, facing -z
  addQuad(s, o, x, z, wall);           // floor, facing +y
  addQuad(s, o + y, z, x, wall);       // ceiling, facing -y
  addQuad(s, o, z, y, wall);           // left, facing +x
  addQuad(s, o + x, y, z, wall);       // right, facing -x
  return s;
}

}  // namespace

// analyticdirect at the pixel that sees the origin: (kd / pi) L (Phi . n) against the form
// factor's closed form, kd L F, to float32 rounding.
TEST(GpuPath, AnalyticDirectMatchesTheClosedFormUnderASquareLight) {
  VKRT_REQUIRE_GPU(context);
  const double h = 1.5;
  const dvec3 kd(0.8, 0.5, 0.25), radiance(3.0, 2.0, 1.0);
  for (bool corner : {false, true}) {
    RadianceImage img = renderPath(floorUnderSquareLight(h, corner, kd, radiance));
    ASSERT_EQ(img.width, 9);
    double f = corner ? cornerFormFactor(2, 2, h) : 4 * cornerFormFactor(1, 1, h);
    for (int c = 0; c < 3; ++c) {
      double expected = kd[c] * radiance[c] * f;
      EXPECT_NEAR(img.pixel(4, 4)[c], expected, 2e-6 * expected + 1e-7) << (corner ? "corner" : "centre") << " c " << c;
    }
  }
}

// `direct` at the same pixel: light sampling of the square (unstratified and stratified)
// estimates the same integral. Sixteen renders of disjoint sample ranges are independent
// estimates of the pixel; a t-test (15 degrees of freedom) at a false-alarm rate of 1e-4 per
// channel and setting.
TEST(GpuPath, DirectConvergesToTheClosedForm) {
  VKRT_REQUIRE_GPU(context);
  const double h = 1.5;
  const dvec3 kd(0.8, 0.5, 0.25), radiance(3.0, 2.0, 1.0);
  SceneDesc s = floorUnderSquareLight(h, false, kd, radiance);
  s.path.integrator = Integrator::Direct;
  const double f = 4 * cornerFormFactor(1, 1, h);
  const int batches = 16;
  const double critical = studentCritical(1e-4, batches - 1);
  for (bool stratify : {false, true}) {
    s.path.lightSamples = 4;
    s.path.lightStratify = stratify;
    double sum[3] = {}, sum2[3] = {};
    for (int k = 0; k < batches; ++k) {
      VulkanPathOptions o;
      o.renderSpp = 1;   // every sample through the pixel centre
      o.firstSample = static_cast<std::uint32_t>(4 * k);
      o.sampleCount = 4;
      RadianceImage img = renderPath(s, o);
      ASSERT_EQ(img.width, 9);
      for (int c = 0; c < 3; ++c) {
        sum[c] += img.pixel(4, 4)[c];
        sum2[c] += double(img.pixel(4, 4)[c]) * img.pixel(4, 4)[c];
      }
    }
    for (int c = 0; c < 3; ++c) {
      double mean = sum[c] / batches, sd = std::sqrt((sum2[c] - batches * mean * mean) / (batches - 1));
      double expected = kd[c] * radiance[c] * f;
      EXPECT_GT(sd, 0.0);
      EXPECT_LE(std::abs(mean - expected) / (sd / std::sqrt(batches)), critical)
          << (stratify ? "stratified" : "uniform") << " channel " << c << ": " << mean << " vs " << expected;
    }
  }
}

// GGX of roughness 0 (`brdf ggx` without `roughness`) gives no NaN (renderPath checks).
TEST(GpuPath, GgxOfRoughnessZeroIsFinite) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(12);
  for (Material& m : s.materials)
    if (m.brdf == BrdfModel::Ggx) m.roughness = 0.0;
  for (Sampling sampling : {Sampling::Brdf, Sampling::Cosine}) {
    s.path.sampling = sampling;
    s.path.nextEvent = NextEvent::Mis;
    VulkanPathOptions o;
    o.sampleCount = 4;
    renderPath(s, o);
  }
}

// Every wall emits Le and reflects a: with maxdepth D every sample is exactly the geometric
// sum (cosine sampling makes each bounce's weight exactly a); without a limit, Russian
// roulette ends the paths and the mean converges to Le / (1 - a). The test: a t-test of the
// pixel means (independent, of one expected value) at a false-alarm rate of 1e-4 per channel.
TEST(GpuPath, WhiteFurnaceConvergesToLeOverOneMinusAlbedo) {
  VKRT_REQUIRE_GPU(context);
  const double a = 0.5, le = 0.25;
  SceneDesc s = furnaceScene(a, le);
  s.path.sampling = Sampling::Cosine;
  s.maxDepth = 3;
  VulkanPathOptions o;
  o.sampleCount = 2;
  RadianceImage depth3 = renderPath(s, o);
  // Every sample is the series, but for the few paths that leave the box: from within the ray
  // offset (1e-3) of an edge, a ray toward the adjacent wall ignores it (doc/scene-format.md, "Conventions").
  const double series = le * (1 + a + a * a + a * a * a);
  std::size_t exact = 0;
  for (float v : depth3.rgb) {
    EXPECT_LE(v, series + 1e-6);
    exact += std::abs(v - series) < 1e-6;
  }
  EXPECT_GE(exact, depth3.rgb.size() * 99 / 100);
  s.maxDepth = -1;
  s.path.russianRoulette = true;
  s.path.sampling = Sampling::Hemisphere;
  o.sampleCount = 16;
  o.seed = 7;
  RadianceImage unlimited = renderPath(s, o);
  save(unlimited, "furnace");
  const double expected = le / (1 - a);
  const int n = unlimited.width * unlimited.height;
  const double critical = studentCritical(1e-4, n - 1);
  for (int c = 0; c < 3; ++c) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      double v = unlimited.rgb[3 * i + c];
      sum += v;
      sum2 += v * v;
    }
    double mean = sum / n, sd = std::sqrt((sum2 - n * mean * mean) / (n - 1));
    double t = (mean - expected) / (sd / std::sqrt(n));
    EXPECT_LE(std::abs(t), critical) << "channel " << c << ": mean " << mean << ", expected " << expected;
    EXPECT_GT(sd, 0.0);
  }
}

TEST(GpuPath, SameSeedSameBitsOtherSeedOtherImage) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(16);
  s.path.nextEvent = NextEvent::Mis;
  s.path.sampling = Sampling::Brdf;
  VulkanPathOptions o;
  o.sampleCount = 4;
  o.seed = 3;
  o.variant = ShaderVariant::Specialized;   // quad lights only: the module without the other lights' code
  RadianceImage a = renderPath(s, o), b = renderPath(s, o);
  EXPECT_TRUE(sameBits(a, b));
  o.seed = 4;
  EXPECT_FALSE(sameBits(a, renderPath(s, o)));
  // Storage and texel reads differ only in their loads.
  o.seed = 3;
  o.reads = SceneReads::Storage;
  EXPECT_TRUE(sameBits(a, renderPath(s, o)));
  o.reads = SceneReads::Texel;
  EXPECT_TRUE(sameBits(a, renderPath(s, o)));
  // Specialization compiles out only what the scene lacks: the general variant (every feature
  // on, but the module of quad lights alone: VKRT_QUAD_LIGHTS_ONLY) renders the same image
  // (pathVariantsAgree: the same bits on lavapipe).
  o.variant = ShaderVariant::General;
  EXPECT_TRUE(pathVariantsAgree(*context, a, renderPath(s, o)));
  // A black point light adds nothing, but takes the whole module, with every light's code:
  // the same image, specialised and general.
  SceneDesc black = s;
  black.lights.push_back(Light{LightType::Point, dvec3(0.0, 1.5, 0.0), dvec3(0.0), dvec3(1.0, 0.0, 0.0)});
  for (ShaderVariant v : {ShaderVariant::Specialized, ShaderVariant::General}) {
    o.variant = v;
    EXPECT_TRUE(pathVariantsAgree(*context, a, renderPath(black, o))) << (v == ShaderVariant::General ? "general" : "specialised");
  }
  // With a point light too: the whole module, specialised and general.
  s.lights.push_back(Light{LightType::Point, dvec3(0.0, 1.5, 0.0), dvec3(0.5), dvec3(1.0, 0.0, 0.0)});
  o.variant = ShaderVariant::Specialized;
  const RadianceImage withPoint = renderPath(s, o);
  EXPECT_FALSE(sameBits(a, withPoint));
  o.variant = ShaderVariant::General;
  EXPECT_TRUE(pathVariantsAgree(*context, withPoint, renderPath(s, o)));
}

// The sampler is specialised in the general variant too (independent and stratified samples
// each have their own): stratified samples render the same image general and specialised
// (pathVariantsAgree: the same bits on lavapipe), and not that of independent samples.
TEST(GpuPath, StratifiedSamplesAgreeGeneralAndSpecialised) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(16);
  VulkanPathOptions o;
  o.sampleCount = 4;
  o.renderSpp = 4;
  o.seed = 5;
  o.variant = ShaderVariant::Specialized;
  const RadianceImage independent = renderPath(s, o);
  o.stratified = true;
  const RadianceImage stratified = renderPath(s, o);
  EXPECT_FALSE(sameBits(independent, stratified));
  o.variant = ShaderVariant::General;
  EXPECT_TRUE(pathVariantsAgree(*context, stratified, renderPath(s, o)));
  o.stratified = false;
  EXPECT_TRUE(pathVariantsAgree(*context, independent, renderPath(s, o)));
}

// A crop draws the numbers and camera rays of the full image: its pixels are the full
// render's, bit for bit.
TEST(GpuPath, CropIsTheFullRendersRegionBitForBit) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(20);
  s.path.nextEvent = NextEvent::On;
  s.path.lightSamples = 4;
  s.path.lightStratify = true;
  VulkanPathOptions o;
  o.sampleCount = 3;
  o.seed = 11;
  RadianceImage full = renderPath(s, o);
  o.crop = PixelRect{3, 5, 17, 12};
  RadianceImage crop = renderPath(s, o);
  ASSERT_EQ(crop.width, 14);
  ASSERT_EQ(crop.height, 7);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      ASSERT_EQ(std::memcmp(crop.pixel(x, y), full.pixel(x + 3, y + 5), 3 * sizeof(float)), 0) << x << "," << y;
}

// A pixel that runs out of steps saves its state and resumes in the next dispatch: the image
// must be the same, bit for bit, as with a budget that never runs out (unlimited depth with
// Russian roulette, MIS, point lights, every kind of step).
namespace {

// A render that suspends after every few steps is the one that never suspends, bit for bit.
// The BVH walk, suspended within a traversal, and the test of every primitive (for scenes
// small enough), whose rays wait whole for the next dispatch (and take 5 steps each).
// `sameWalk`: the two traversals give the same bits too.
void expectSuspensionChangesNoBit(const SceneDesc& s, bool sameWalk) {
  RadianceImage walked;
  for (bool testAll : {false, true}) {
    VulkanPathOptions o;
    o.testAll = testAll;
    o.sampleCount = 3;
    o.stepBudget = 13000;   // within llvmpipe's limit (13000 x (1 + kMaxLeafPrims) < 65,535)
    VulkanTimings whole, pieces;
    RadianceImage a = renderPath(s, o, nullptr, &whole);
    EXPECT_EQ(whole.testedAll, testAll);
    if (!testAll) walked = a;
    EXPECT_TRUE(!sameWalk || sameBits(walked, a)) << "testing every primitive against the BVH walk";
    EXPECT_EQ(whole.suspensions, 0u) << "make the scene easier: the reference render must not suspend";
    for (std::uint32_t budget : {2u, 5u, 37u}) {
      o.stepBudget = budget;
      RadianceImage b = renderPath(s, o, nullptr, &pieces);
      EXPECT_GT(pieces.suspensions, testAll ? 500u : 1000u) << "budget " << budget;
      EXPECT_TRUE(sameBits(a, b)) << "budget " << budget << (testAll ? ", every primitive tested" : ", BVH");
    }
  }
}

}  // namespace

TEST(GpuPath, SuspendingAfterEveryFewStepsChangesNoBit) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(16);
  s.maxDepth = -1;
  s.path.russianRoulette = true;
  s.path.nextEvent = NextEvent::Mis;
  s.path.sampling = Sampling::Brdf;
  s.path.lightSamples = 2;
  Light point;
  point.type = LightType::Point;
  point.vec = dvec3(0.5, 1.5, 0.5);
  point.color = dvec3(0.3, 0.3, 0.3);
  s.lights.push_back(point);
  expectSuspensionChangesNoBit(s, true);
}

// The same with emissive triangles and an ellipsoid sampled as lights (the emitter table's
// search counts its steps).
TEST(GpuPath, SuspendingWithEmittersChangesNoBit) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = test::emissiveSurfacesBox(16, -1);
  s.path.russianRoulette = true;
  s.path.nextEvent = NextEvent::Mis;
  s.path.sampling = Sampling::Brdf;
  s.path.lightSamples = 2;
  // Not bit for bit across traversals: the box is symmetric about the camera and a render of
  // spp 1 samples pixel centres, so the centres on the image's diagonals see exactly the edges
  // where the ceiling meets the side walls, a tie of two triangles that the walk and the test
  // of every primitive settle in their own orders (6 of 256 pixels differ). Each traversal
  // against itself is exact.
  expectSuspensionChangesNoBit(s, false);
}

// A lane renders the samples of several pixels in turn (one of each tile of its workgroup's
// run), and a paced render sizes its bands by time: neither changes a bit, whether the lanes
// suspend or not, in bands of 8 rows or of the whole image, for a crop too.
TEST(GpuPath, PixelsPerLaneAndBandsChangeNoBit) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(44);   // tiles that stick out of the image on the right and bottom
  s.maxDepth = -1;
  s.path.russianRoulette = true;
  s.path.nextEvent = NextEvent::Mis;
  for (std::optional<PixelRect> crop : {std::optional<PixelRect>(), std::optional<PixelRect>(PixelRect{3, 5, 41, 30})}) {
    VulkanPathOptions o;
    o.sampleCount = 3;
    o.seed = 5;
    o.crop = crop;
    o.pixelsPerInvocation = 1;
    o.stepBudget = 13000;
    VulkanTimings whole;
    RadianceImage reference = renderPath(s, o, nullptr, &whole);
    ASSERT_EQ(whole.suspensions, 0u);
    for (std::uint32_t perLane : {1u, 3u, 16u})
      for (std::uint32_t budget : {0u, 7u, 13000u})
        for (std::size_t stateBytes : {std::size_t{1}, std::size_t{64} << 20}) {
          o.pixelsPerInvocation = perLane;
          o.stepBudget = budget;
          o.maxStateBytes = stateBytes;
          VulkanTimings t;
          RadianceImage got = renderPath(s, o, nullptr, &t);
          EXPECT_TRUE(sameBits(reference, got)) << perLane << " pixels a lane, budget " << budget << ", "
                                                << stateBytes << " state bytes" << (crop ? ", crop" : "");
          if (stateBytes == 1) {
            EXPECT_GE(t.bands, 4u);
          }
          if (budget == 7) {
            EXPECT_GT(t.suspensions, 100u);
          }
        }
  }
}

// The progress of a path render moves with every dispatch (the samples the shader finished),
// not once a band: at a small budget, many times within the first band, never backwards, and
// to the whole count at the end.
TEST(GpuPath, ProgressMovesWithEveryDispatch) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(32);
  VulkanPathOptions o;
  o.sampleCount = 4;
  o.stepBudget = 20;
  o.maxStateBytes = 1;   // bands of 8 rows
  std::vector<std::uint64_t> done;
  std::uint64_t total = 0;
  o.progress = [&](std::uint64_t d, std::uint64_t t) {
    done.push_back(d);
    total = t;
  };
  VulkanTimings t;
  renderPath(s, o, nullptr, &t);
  const std::uint64_t firstBand = 8u * 32u * 4u;
  ASSERT_EQ(total, 32u * 32u * 4u);
  ASSERT_EQ(done.size(), t.dispatches);
  EXPECT_GT(std::count_if(done.begin(), done.end(), [&](std::uint64_t d) { return d > 0 && d < firstBand; }), 3)
      << "the bar stood still through the first band";
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_EQ(done.back(), total);
}

// A small scene's rays test every primitive, triangles then spheres, instead of walking the
// BVH: the same image bit for bit (no two primitives of these scenes tie at a hit).
TEST(GpuPath, TestingEveryPrimitiveChangesNoBit) {
  VKRT_REQUIRE_GPU(context);
  for (NextEvent nee : {NextEvent::Off, NextEvent::Mis}) {
    SceneDesc s = boxScene(24);
    s.path.nextEvent = nee;
    Sphere small = s.spheres[0];
    small.center = dvec3(-0.35, 0.85, 0.1);
    small.radius = 0.15;
    s.spheres.push_back(small);
    VulkanPathOptions o;
    o.sampleCount = 4;
    o.testAll = false;
    VulkanTimings walked, tested;
    RadianceImage a = renderPath(s, o, nullptr, &walked);
    o.testAll = true;
    RadianceImage b = renderPath(s, o, nullptr, &tested);
    EXPECT_FALSE(walked.testedAll);
    EXPECT_TRUE(tested.testedAll);
    EXPECT_TRUE(sameBits(a, b));
  }
}

// Batches [0, 4) and [4, 8) average to the render of [0, 8) (up to the order of float sums).
TEST(GpuPath, SampleBatchesAverageToOneRender) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(12);
  s.path.nextEvent = NextEvent::On;
  VulkanPathOptions o;
  o.seed = 5;
  o.sampleCount = 8;
  RadianceImage all = renderPath(s, o);
  EXPECT_EQ(all.samples, 8u);
  o.sampleCount = 4;
  o.renderSpp = 8;
  RadianceImage first = renderPath(s, o);
  o.firstSample = 4;
  RadianceImage second = renderPath(s, o);
  for (std::size_t i = 0; i < all.rgb.size(); ++i)
    ASSERT_NEAR(all.rgb[i], 0.5f * (first.rgb[i] + second.rgb[i]), 1e-5f * std::max(1.0f, all.rgb[i])) << i;
}

// The batches of one VulkanPathRender upload the scene once, and each is the image of a render
// of its own, bit for bit; batches of another sample count (another band layout) among them.
TEST(GpuPath, BatchesOfOneRenderShareTheUploadAndChangeNoBit) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(12);
  s.path.nextEvent = NextEvent::On;
  const GpuScene scene = flatten(s);
  VulkanPathRender render(*context, scene);
  const int before = context->validationMessages();
  std::uint32_t first = 0;
  for (std::uint32_t count : {1u, 3u, 1u, 6u}) {
    VulkanPathOptions o;
    o.seed = 9;
    o.firstSample = first;
    o.sampleCount = count;
    o.renderSpp = 11;
    first += count;
    VulkanTimings shared;
    RadianceImage batch = render.render(o, nullptr, &shared);
    RadianceImage alone = renderPath(s, o);
    EXPECT_EQ(batch.samples, count);
    EXPECT_TRUE(sameBits(batch, alone)) << "samples from " << o.firstSample;
  }
  EXPECT_EQ(render.uploads(), 1u);
  EXPECT_EQ(context->validationMessages(), before) << "the Vulkan validation layer reported problems (see stderr)";
}

// A render of spp 1 samples the pixel centres (gpu_types.h, the camera rule).
TEST(GpuPath, SppOneSamplesPixelCentres) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(12);
  s.path.integrator = Integrator::AnalyticDirect;   // no noise: the image depends only on the rays
  VulkanPathOptions o;
  o.sampleCount = 1;
  o.renderSpp = 1;
  RadianceImage centre = renderPath(s, o);
  o.seed = 9;
  EXPECT_TRUE(sameBits(centre, renderPath(s, o)));
  o.renderSpp = 2;
  EXPECT_FALSE(sameBits(centre, renderPath(s, o)));
}

// The depth rule (doc/path-tracing.md, "Estimators"): maxdepth 0 shows only what the camera sees
// emitting, and maxdepth 1 is direct lighting: the `direct` integrator's expected image.
TEST(GpuPath, MaxDepthZeroShowsEmittersOnly) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc s = boxScene(16);
  s.maxDepth = 0;
  s.path.nextEvent = NextEvent::On;
  VulkanPathOptions o;
  o.sampleCount = 2;
  RadianceImage img = renderPath(s, o);
  int lit = 0;
  for (int i = 0; i < img.width * img.height; ++i) {
    // Of the two samples none, one or both saw the light (8, 7, 6): exact in float.
    const float* p = img.rgb.data() + 3 * i;
    float k = p[0] / 8.0f;
    EXPECT_TRUE((k == 0.0f || k == 0.5f || k == 1.0f) && p[1] == 7.0f * k && p[2] == 6.0f * k) << i;
    lit += k == 1.0f;
  }
  EXPECT_GT(lit, 0);
}

namespace {

constexpr int kStrategyBlocks = 16;   // 8x8 blocks of the 32x32 image

// doc/path-tracing.md, "Estimators"'s invariant: NEE off, on and MIS (and with them Russian
// roulette, the three samplings, light samples and strata) change the noise, not the
// expected image. Per-block t-tests (8x8 blocks of a 32x32 image) against NEE on, family
// false-alarm rate 1e-3 over all the tests of one call, each image of `samples` samples per
// pixel. Returns the reference image.
RadianceImage expectStrategiesAgree(const SceneDesc& base, const std::string& name, std::uint32_t firstSeed,
                                    std::uint32_t samples) {
  VulkanPathOptions o;
  o.sampleCount = samples;
  struct Variant {
    const char* name;
    NextEvent nee;
    Sampling sampling;
    bool rr;
    int lightSamples;
    bool stratify;
  };
  const Variant variants[] = {
      {"nee-off-cosine", NextEvent::Off, Sampling::Cosine, false, 1, false},
      {"nee-mis-brdf", NextEvent::Mis, Sampling::Brdf, false, 1, false},
      {"nee-mis-hemisphere-rr", NextEvent::Mis, Sampling::Hemisphere, true, 4, true},
      {"nee-on-brdf-rr-4", NextEvent::On, Sampling::Brdf, true, 4, false},
  };
  SceneDesc refScene = base;
  refScene.path.nextEvent = NextEvent::On;
  refScene.path.sampling = Sampling::Cosine;
  o.seed = 1000;
  RadianceImage reference = renderPath(refScene, o);
  save(reference, name + "-reference");
  const int tests = kStrategyBlocks * 3 * static_cast<int>(std::size(variants));
  std::uint32_t seed = firstSeed;
  for (const Variant& v : variants) {
    SceneDesc s = base;
    s.path.nextEvent = v.nee;
    s.path.sampling = v.sampling;
    s.path.russianRoulette = v.rr;
    s.path.lightSamples = v.lightSamples;
    s.path.lightStratify = v.stratify;
    o.seed = seed++;
    RadianceImage img = renderPath(s, o);
    auto failures = blockTTests(img, reference, 8, 1e-3, tests);
    if (!failures.empty()) save(img, name + "-" + v.name);
    EXPECT_TRUE(failures.empty()) << name << " " << v.name << ": " << failures.size() << " blocks differ, first "
                                  << failures[0];
  }
  return reference;
}

}  // namespace

TEST(GpuPathSlow, StrategiesConvergeToTheSameImage) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc base = boxScene(32);
  base.maxDepth = 3;
  const RadianceImage reference = expectStrategiesAgree(base, "strategies", 1, 64);
  // The test's power: one bounce more (maxdepth 4) is a different image, and must be told apart.
  SceneDesc deeper = base;
  deeper.maxDepth = 4;
  deeper.path.nextEvent = NextEvent::On;
  deeper.path.sampling = Sampling::Cosine;
  VulkanPathOptions o;
  o.sampleCount = 64;
  o.seed = 5;
  EXPECT_FALSE(blockTTests(renderPath(deeper, o), reference, 8, 1e-3, kStrategyBlocks * 3 * 4).empty());
}

// A diffuse floor beside a near-mirror Phong sphere (shininess 1000) and a small quad light
// (path_scenes.h, floorBesideMirrorSphere), maxdepth 2: cosine sampling with NEE finds the
// light reaching the floor through the sphere only by the light samples at the sphere, BRDF
// sampling with MIS mostly by the sphere's sampled rays, weighted. Tolerance: per-block
// t-tests of the pixel differences (blockTTests, 8x8 blocks), family false-alarm rate 1e-3,
// each image of 256 samples per pixel.
TEST(GpuPath, MirrorLobeUnderASmallLightCosineNeeMatchesBrdfMis) {
  VKRT_REQUIRE_GPU(context);
  SceneDesc cosine = test::floorBesideMirrorSphere(32, 2);
  cosine.path.nextEvent = NextEvent::On;
  cosine.path.sampling = Sampling::Cosine;
  SceneDesc mis = cosine;
  mis.path.nextEvent = NextEvent::Mis;
  mis.path.sampling = Sampling::Brdf;
  VulkanPathOptions o;
  o.sampleCount = 256;
  o.seed = 41;
  const RadianceImage a = renderPath(cosine, o);
  o.seed = 42;
  const RadianceImage b = renderPath(mis, o);
  auto failures = blockTTests(a, b, 8, 1e-3, kStrategyBlocks * 3);
  if (!failures.empty()) {
    save(a, "mirror-lobe-cosine-nee");
    save(b, "mirror-lobe-brdf-mis");
  }
  EXPECT_TRUE(failures.empty()) << failures.size() << " blocks differ, first " << failures[0];
}

// The same with emissive triangles and an ellipsoid (no quad light) sampled as lights (NEE
// on, mis) or found by hitting only (off).
TEST(GpuPathSlow, EmissiveSurfacesAsLights) {
  VKRT_REQUIRE_GPU(context);
  expectStrategiesAgree(test::emissiveSurfacesBox(32, 3), "emitters", 11, 1024);
}

// Every course scene of hw2-hw4 renders on the GPU: a 24x24 crop below the image's centre, one
// sample per pixel (the dragons' 100,000 triangles included), no NaN, the validation layer
// silent, something lit.
class GpuPathCourseScene : public ::testing::TestWithParam<const char*> {};

TEST_P(GpuPathCourseScene, RendersACropWithoutNaN) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  VKRT_REQUIRE_GPU(context);
  SceneDesc scene = parseSceneFile(*dir + "/scenes/" + GetParam() + ".test");
  VulkanPathOptions o;
  o.sampleCount = 1;
  const int x0 = scene.width / 2 - 12, y0 = scene.height * 3 / 4 - 12;
  o.crop = PixelRect{x0, y0, x0 + 24, y0 + 24};
  RadianceImage img = renderPath(scene, o);
  ASSERT_EQ(img.width, 24);
  float brightest = 0;
  for (float v : img.rgb) brightest = std::max(brightest, v);
  EXPECT_GT(brightest, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Cse168, GpuPathCourseScene,
                         ::testing::Values("hw2/analytic", "hw2/cornell", "hw2/direct3x3", "hw2/direct9", "hw2/dragon",
                                           "hw2/sphere", "hw3/cornellNEE", "hw3/cornellRR", "hw3/cornellSimple",
                                           "hw3/dragon", "hw4/cornellBRDF", "hw4/cornellCosine", "hw4/cornellMIS",
                                           "hw4/dragon", "hw4/ggx", "hw4/mis"),
                         [](const auto& p) { return testName(std::string(p.param).replace(3, 1, "_")); });

// The random numbers a path vertex draws for its light samples, counted against the slots the
// shader has (gpu_rng.h): under `direct` as under the path tracer with next-event estimation,
// two a quad-light sample; analyticdirect draws none, nor a path tracer without next-event
// estimation. At the limit the scene renders; one sample past it is refused, said in the
// scene's terms.
TEST(LightSlots, DirectCountsItsQuadLightSamplesUpToTheLimit) {
  const std::uint32_t slots = gpu::kRngBounceStride - gpu::kRngSlotLightBase;
  for (std::uint32_t integrator : {gpu::kIntegratorDirect, gpu::kIntegratorPathTracer}) {
    gpu::GpuPathParams p{};
    p.integrator = integrator;
    p.nextEvent = gpu::kNextEventOn;
    p.quadLightCount = 4;
    p.lightSamples = slots / 8;
    EXPECT_EQ(lightSlotsProblem(p, false), "") << "integrator " << integrator;
    p.lightSamples = slots / 8 + 1;
    const std::string problem = lightSlotsProblem(p, false);
    EXPECT_NE(problem.find("4 quad lights x " + std::to_string(slots / 8 + 1) + " lightsamples x 2"), std::string::npos)
        << "integrator " << integrator << ": " << problem;
  }
  gpu::GpuPathParams p{};
  p.quadLightCount = 4;
  p.lightSamples = slots;
  p.integrator = gpu::kIntegratorAnalyticDirect;
  EXPECT_EQ(lightSlotsProblem(p, true), "");
  p.integrator = gpu::kIntegratorPathTracer;
  p.nextEvent = gpu::kNextEventOff;
  EXPECT_EQ(lightSlotsProblem(p, true), "");
}
