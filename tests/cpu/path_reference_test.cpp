// The CPU path integrators against closed forms (analyticdirect, a white furnace), against
// each other in expectation (direct = analyticdirect), and for reproducibility (seeds,
// sample batches, crops). Statistical tests state their false-alarm rate: each is the chance
// that a correct integrator fails for a seed drawn at random; with the fixed seeds below the
// tests are deterministic.
#include <cmath>
#include <filesystem>
#include <numeric>

#include <gtest/gtest.h>

#include "cpu/path_reference.h"
#include "path_scenes.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "test_support.h"

namespace vkrt {
namespace {

using test::addMaterial;
using test::addQuad;
using test::addQuadLight;
using test::setCamera;

constexpr double kPi = 3.14159265358979323846;

RadianceImage render(const SceneDesc& scene, std::uint32_t seed = 1, std::uint32_t first = 0, std::uint32_t count = 0,
                     RayCounts* counts = nullptr) {
  PathOptions options;
  options.seed = seed;
  options.firstSample = first;
  options.sampleCount = count;
  RayCounts local;
  RadianceImage image = renderPathReference(scene, buildBvh(scene), options, counts ? counts : &local);
  EXPECT_EQ((counts ? counts : &local)->nonFinite, 0u);
  return image;
}

// The view factor from a surface element to a parallel a x b rectangle at height h, the
// element below one of its corners (the textbook closed form, e.g. Howell's catalogue C-11).
double cornerViewFactor(double a, double b, double h) {
  const double x = a / h, y = b / h;
  return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
          y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
         (2 * kPi);
}

// A diffuse floor (y = 0, facing up) under a w x d light at height h facing down, centred
// over the origin.
SceneDesc floorUnderLight(double w, double d, double h, const dvec3& kd, const dvec3& radiance) {
  SceneDesc s;
  Material floor;
  floor.ambient = dvec3(0.0);
  floor.diffuse = kd;
  addQuad(s, dvec3(-5, 0, -5), dvec3(10, 0, 0), dvec3(0, 0, 10), addMaterial(s, floor));
  addQuadLight(s, dvec3(-w / 2, h, -d / 2), dvec3(0, 0, d), dvec3(w, 0, 0), radiance);
  return s;
}

// ---- a. analyticdirect is the closed form --------------------------------------------------

TEST(AnalyticDirect, PointBelowTheCentreOfARectangularLight) {
  const double w = 0.6, d = 0.4, h = 1.3;
  const dvec3 kd(0.5, 0.25, 1.0), radiance(1.0, 2.0, 3.0);
  SceneDesc s = floorUnderLight(w, d, h, kd, radiance);
  // One pixel: its centre's ray hits the floor at the origin, passing beside the light.
  setCamera(s, dvec3(2.0, 0.5, 0.0), dvec3(0.0), 30.0, 1, 1);
  s.path.integrator = Integrator::AnalyticDirect;
  const RadianceImage image = render(s);
  // Four corner rectangles of w/2 x d/2: radiance = kd / pi * E = kd * L * F.
  const double viewFactor = 4 * cornerViewFactor(w / 2, d / 2, h);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(image.rgb[k], kd[k] * radiance[k] * viewFactor, 1e-7 * kd[k] * radiance[k] * viewFactor)
        << "channel " << k << " (float32 image)";
  // The double factor itself, to 1e-9 relative (below the centre, and below a corner).
  EXPECT_NEAR(analyticQuadFactor(s.quadLights[0], dvec3(0.0), dvec3(0, 1, 0)), kPi * viewFactor, 1e-9 * kPi * viewFactor);
  const double cornerFactor = kPi * cornerViewFactor(w, d, h);
  EXPECT_NEAR(analyticQuadFactor(s.quadLights[0], dvec3(-w / 2, 0, -d / 2), dvec3(0, 1, 0)), cornerFactor,
              1e-9 * cornerFactor);
  // One-sided: a point above the light sees its black back.
  EXPECT_EQ(analyticQuadFactor(s.quadLights[0], dvec3(0, 2 * h, 0), dvec3(0, -1, 0)), 0.0);
}

// ---- b. the white furnace ------------------------------------------------------------------

// Mean and standard error of the mean of the image's per-pixel means (channel 0): in a
// furnace every pixel has the same expectation and the pixels are independent.
struct MeanAndError {
  double mean, error;
};
MeanAndError pixelStatistics(const RadianceImage& image) {
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  double sum = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += image.rgb[3 * i];
  const double count = static_cast<double>(n), mean = sum / count;
  for (std::size_t i = 0; i < n; ++i) squares += (image.rgb[3 * i] - mean) * (image.rgb[3 * i] - mean);
  return {mean, std::sqrt(squares / (count - 1) / count)};
}

// |z| > 3.89: a false alarm with probability 1e-4 (two-sided, normal; n = 1024 pixel means).
constexpr double kZ1e4 = 3.89;

double truncatedSeries(double albedo, double emission, int maxDepth) {
  double sum = 0.0, term = emission;
  for (int k = 0; k <= maxDepth; ++k, term *= albedo) sum += term;
  return sum;
}

TEST(PathFurnace, CosineSamplingIsExactAtEveryDepth) {
  // beta = f cos / pdf = (a / pi) cos / (cos / pi) = a: no noise, only rounding.
  for (int depth : {0, 1, 2, 7}) {
    SceneDesc s = test::furnaceBox(0.6, 0.5, 4);
    s.maxDepth = depth;
    s.path.sampling = Sampling::Cosine;
    s.path.spp = 2;
    const RadianceImage image = render(s);
    for (float v : image.rgb) EXPECT_NEAR(v, truncatedSeries(0.6, 0.5, depth), 1e-6) << "maxdepth " << depth;
  }
}

TEST(PathFurnace, ConvergesToTheGeometricSeries) {
  struct Case {
    Sampling sampling;
    bool roulette;
    NextEvent nee;
    int maxDepth;
  };
  const Case cases[] = {{Sampling::Hemisphere, true, NextEvent::Off, -1}, {Sampling::Brdf, true, NextEvent::Mis, -1},
                        {Sampling::Hemisphere, false, NextEvent::On, 4}, {Sampling::Cosine, true, NextEvent::Off, 3},
                        {Sampling::Hemisphere, true, NextEvent::Off, 6}};
  const double albedo = 0.7, emission = 0.3;
  for (const Case& c : cases) {
    SceneDesc s = test::furnaceBox(albedo, emission, 32);
    s.maxDepth = c.maxDepth;
    s.path.sampling = c.sampling;
    s.path.russianRoulette = c.roulette;
    s.path.nextEvent = c.nee;
    s.path.spp = 8;
    const double expected = c.maxDepth < 0 ? emission / (1 - albedo) : truncatedSeries(albedo, emission, c.maxDepth);
    const MeanAndError m = pixelStatistics(render(s, 7));
    const double z = (m.mean - expected) / m.error;
    EXPECT_LT(std::abs(z), kZ1e4) << "sampling " << int(c.sampling) << " roulette " << c.roulette << " maxdepth "
                                  << c.maxDepth << ": mean " << m.mean << " +- " << m.error << ", expected " << expected;
    EXPECT_GT(m.error, 0.0);   // the estimator is noisy here: the test has power
  }
}

// ---- d. direct = analyticdirect in expectation ---------------------------------------------

TEST(PathDirect, EqualsAnalyticDirectInExpectation) {
  // An unoccluded diffuse floor under a light. Both integrators draw the same pixel positions
  // (same seed and samples), and analyticdirect is then the exact expectation of direct, so
  // the per-pixel difference has mean 0; its mean over the 1024 independent pixels is z-tested
  // (false alarm 1e-4 per case).
  for (bool stratify : {false, true})
    for (int n : {1, 4}) {
      SceneDesc s = floorUnderLight(0.8, 0.5, 1.0, dvec3(0.6, 0.5, 0.4), dvec3(3.0, 3.0, 3.0));
      setCamera(s, dvec3(0.0, 2.5, 2.5), dvec3(0.0), 50.0, 32, 32);
      s.path.spp = 4;
      s.path.lightSamples = n;
      s.path.lightStratify = stratify;
      s.path.integrator = Integrator::Direct;
      const RadianceImage direct = render(s, 3);
      s.path.integrator = Integrator::AnalyticDirect;
      const RadianceImage exact = render(s, 3);
      RadianceImage difference(32, 32);
      for (std::size_t i = 0; i < direct.rgb.size(); ++i) difference.rgb[i] = direct.rgb[i] - exact.rgb[i];
      const MeanAndError m = pixelStatistics(difference);
      EXPECT_LT(std::abs(m.mean / m.error), kZ1e4) << "lightsamples " << n << " stratify " << stratify << ": "
                                                    << m.mean << " +- " << m.error;
      EXPECT_GT(m.error, 0.0);
    }
}

// ---- e. reproducibility --------------------------------------------------------------------

SceneDesc smallCornell() {
  SceneDesc s = test::cornellLikeBox(24, 3);
  s.path.nextEvent = NextEvent::Mis;
  s.path.sampling = Sampling::Brdf;
  s.path.russianRoulette = true;
  s.path.spp = 6;
  return s;
}

TEST(PathReproducible, SameSeedSameBitsOtherSeedOtherImage) {
  const SceneDesc s = smallCornell();
  const RadianceImage a = render(s, 11), b = render(s, 11), c = render(s, 12);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_NE(a.rgb, c.rgb);
  EXPECT_EQ(a.samples, 6u);
  // Thread count and tile order change nothing.
  PathOptions one;
  one.seed = 11;
  one.threads = 1;
  EXPECT_EQ(renderPathReference(s, buildBvh(s), one, nullptr).rgb, a.rgb);
}

TEST(PathReproducible, BatchesAverageToTheFullRender) {
  const SceneDesc s = smallCornell();
  const RadianceImage full = render(s, 5);
  const RadianceImage first = render(s, 5, 0, 2), rest = render(s, 5, 2, 0);
  EXPECT_EQ(first.samples, 2u);
  EXPECT_EQ(rest.samples, 4u);
  for (std::size_t i = 0; i < full.rgb.size(); ++i) {
    const double averaged = (2.0 * first.rgb[i] + 4.0 * rest.rgb[i]) / 6.0;
    // Each image is rounded to float once: the average is within a few float ulps of the value.
    EXPECT_NEAR(averaged, full.rgb[i], 4e-7 * std::max(1.0, std::abs(double(full.rgb[i])))) << "value " << i;
  }
  // The batches draw different numbers: they are not the same image.
  EXPECT_NE(first.rgb, rest.rgb);
}

TEST(PathReproducible, CropIsTheFullRendersRegion) {
  const SceneDesc s = smallCornell();
  const RadianceImage full = render(s, 9);
  PathOptions options;
  options.seed = 9;
  options.crop = PixelRect{5, 7, 19, 16};
  const RadianceImage crop = renderPathReference(s, buildBvh(s), options, nullptr);
  ASSERT_EQ(crop.width, 14);
  ASSERT_EQ(crop.height, 9);
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(crop.pixel(x, y)[k], full.pixel(x + 5, y + 7)[k]) << x << "," << y;
}

// ---- the depth rule and one-sided lights ---------------------------------------------------

TEST(PathDepth, MaxDepthZeroShowsOnlyWhatTheCameraSeesEmitting) {
  SceneDesc s = test::cornellLikeBox(24, 0);
  s.path.spp = 1;   // pixel centres
  const RadianceImage image = render(s);
  // Only the light (seen from below: its front) is non-zero, and it is exactly its radiance.
  int lit = 0;
  for (int i = 0; i < image.width * image.height; ++i) {
    const float* p = image.rgb.data() + 3 * i;
    if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f) continue;
    ++lit;
    EXPECT_EQ(p[0], 8.0f);
    EXPECT_EQ(p[1], 7.0f);
    EXPECT_EQ(p[2], 6.0f);
  }
  EXPECT_GT(lit, 0);
}

TEST(PathDepth, AQuadLightsBackIsBlackAndReflectsNothing) {
  // The floor's light faces down, away from the floor: nothing reaches it, by any strategy.
  SceneDesc s = floorUnderLight(0.8, 0.5, 1.0, dvec3(0.6), dvec3(3.0));
  s.quadLights[0].ab = dvec3(0.8, 0, 0);   // swap the edges: n = cross(ac, ab) now points up
  s.quadLights[0].ac = dvec3(0, 0, 0.5);
  s.triangles.resize(2);
  addQuad(s, s.quadLights[0].a, s.quadLights[0].ab, s.quadLights[0].ac, 1);
  setCamera(s, dvec3(0.0, 0.5, 2.5), dvec3(0.0, 0.5, 0.0), 60.0, 16, 16);
  s.path.spp = 4;
  s.maxDepth = 4;
  for (Integrator integrator : {Integrator::AnalyticDirect, Integrator::Direct, Integrator::PathTracer})
    for (NextEvent nee : {NextEvent::Off, NextEvent::On, NextEvent::Mis}) {
      s.path.integrator = integrator;
      s.path.nextEvent = nee;
      const RadianceImage image = render(s);
      EXPECT_EQ(*std::max_element(image.rgb.begin(), image.rgb.end()), 0.0f) << int(integrator) << " " << int(nee);
    }
}

// ---- point and directional lights: sampled at every vertex, whatever NEE says ------------

TEST(PathPointLights, DiffuseFloorUnderAPointAndADirectionalLight) {
  // maxdepth 1 and nothing else in the scene: the sampled bounce leaves for the black sky, so
  // one sample at the pixel centre is exact: kd / pi (I / (c + l d + q d^2) cos + I_dir cos).
  SceneDesc s;
  Material floor;
  floor.ambient = dvec3(0.0);
  floor.diffuse = dvec3(0.5, 0.4, 0.3);
  addQuad(s, dvec3(-5, 0, -5), dvec3(10, 0, 0), dvec3(0, 0, 10), addMaterial(s, floor));
  Light point;
  point.type = LightType::Point;
  point.vec = dvec3(0.6, 2.0, 0.0);
  point.color = dvec3(3.0, 2.0, 1.0);
  point.attenuation = dvec3(1.0, 0.5, 0.25);
  Light sun;
  sun.vec = glm::normalize(dvec3(-1.0, 1.0, 0.0));
  sun.color = dvec3(0.2, 0.3, 0.4);
  s.lights = {point, sun};
  setCamera(s, dvec3(0.0, 1.0, 3.0), dvec3(0.0), 30.0, 1, 1);
  s.maxDepth = 1;
  const double d = std::sqrt(0.36 + 4.0), cosPoint = 2.0 / d, cosSun = std::sqrt(0.5);
  for (NextEvent nee : {NextEvent::Off, NextEvent::On, NextEvent::Mis}) {
    for (Integrator integrator : {Integrator::PathTracer, Integrator::Direct}) {
      s.path.integrator = integrator;
      s.path.nextEvent = nee;
      const RadianceImage image = render(s);
      for (int k = 0; k < 3; ++k) {
        const double expected =
            floor.diffuse[k] / kPi * (point.color[k] / (1.0 + 0.5 * d + 0.25 * d * d) * cosPoint + sun.color[k] * cosSun);
        EXPECT_NEAR(image.rgb[k], expected, 1e-6 * expected) << "channel " << k << " nee " << int(nee);
      }
    }
  }
  // A blocker between the floor and the point light leaves only the directional light.
  Material black;
  addQuad(s, dvec3(-0.5, 1.0, -0.5), dvec3(0, 0, 1.4), dvec3(1.4, 0, 0), addMaterial(s, black));
  s.path.integrator = Integrator::PathTracer;
  const RadianceImage shadowed = render(s);
  EXPECT_NEAR(shadowed.rgb[0], 0.5 / kPi * 0.2 * cosSun, 1e-6);
}

// ---- f. the course's scenes ----------------------------------------------------------------

TEST(PathCourseScenes, EveryCse168SceneRendersWithoutNaN) {
  namespace fs = std::filesystem;
  const std::optional<std::string> data = test::cse168Dir();
  if (!data) VKRT_SKIP_UNLESS_CI(test::kNoCse168Data);
  const fs::path dir = fs::path(*data) / "scenes";
  int rendered = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.path().extension() != ".test") continue;
    SCOPED_TRACE(entry.path().string());
    SceneDesc s = parseSceneFile(entry.path().string());
    if (s.path.integrator == Integrator::Raytracer)
      VKRT_SKIP_UNLESS_CI("the parser does not read the path integrators' commands yet");
    // Low resolution and one sample per pixel past the first (the scene's own spp decides
    // whether pixel centres are sampled).
    const double scale = 48.0 / s.width;
    s.width = 48;
    s.height = std::max(1, static_cast<int>(std::lround(s.height * scale)));
    PathOptions options;
    options.sampleCount = 1;
    RayCounts counts;
    const RadianceImage image = renderPathReference(s, buildBvh(s), options, &counts);
    EXPECT_EQ(counts.nonFinite, 0u);
    EXPECT_GT(*std::max_element(image.rgb.begin(), image.rgb.end()), 0.0f) << "a black image";
    ++rendered;
  }
  EXPECT_EQ(rendered, 16);
}

}  // namespace
}  // namespace vkrt
