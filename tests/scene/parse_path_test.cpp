// Parser tests for the commands of doc/path-tracing.md, "Commands", from strings: each value read,
// the defaults, quad lights as geometry (winding, transforms), and the course's 16 scenes.
// Errors and warnings are in parse_errors_test.cpp and parse_warnings_test.cpp.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/parse.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

dvec3 faceNormal(const Triangle& t) { return glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])); }

// The triangles whose material belongs to quad light `index`.
std::vector<Triangle> trianglesOfQuadLight(const SceneDesc& s, int index) {
  std::vector<Triangle> out;
  for (const Triangle& t : s.triangles)
    if (s.materials[t.material].quadLight == index) out.push_back(t);
  return out;
}

// The two triangles of `q` cover its parallelogram: together they use its four corners, each
// has face normal normalize(cross(ac, ab)), and their areas add up to |cross(ab, ac)|.
void expectQuadGeometry(const SceneDesc& s, int index) {
  const QuadLight& q = s.quadLights.at(static_cast<std::size_t>(index));
  std::vector<Triangle> tris = trianglesOfQuadLight(s, index);
  ASSERT_EQ(tris.size(), 2u);
  const dvec3 n = glm::normalize(glm::cross(q.ac, q.ab));
  const dvec3 corners[4] = {q.a, q.a + q.ab, q.a + q.ab + q.ac, q.a + q.ac};
  double area = 0.0;
  bool used[4] = {};
  for (const Triangle& t : tris) {
    expectNear(faceNormal(t), n, 1e-12);
    area += 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    for (const dvec3& p : t.p) {
      bool found = false;
      for (int k = 0; k < 4; ++k)
        if (glm::length(p - corners[k]) < 1e-12) used[k] = found = true;
      EXPECT_TRUE(found) << "a vertex that is not a corner of the quad light";
    }
    EXPECT_FALSE(t.smooth);
  }
  for (bool u : used) EXPECT_TRUE(u);
  EXPECT_NEAR(area, glm::length(glm::cross(q.ab, q.ac)), 1e-12);
  const Material& m = s.materials[tris[0].material];
  EXPECT_EQ(tris[1].material, tris[0].material);
  EXPECT_EQ(m.emission, q.radiance);
  EXPECT_EQ(m.ambient, dvec3(0.0));
  EXPECT_EQ(m.diffuse, dvec3(0.0));
  EXPECT_EQ(m.specular, dvec3(0.0));
  EXPECT_EQ(m.quadLight, index);
}

}  // namespace

TEST(ParsePath, Defaults) {
  SceneDesc s = parseBodyStrict("sphere 0 0 0 1\n");
  EXPECT_EQ(s.path.integrator, Integrator::Raytracer);
  EXPECT_EQ(s.path.spp, 1);
  EXPECT_EQ(s.path.lightSamples, 1);
  EXPECT_FALSE(s.path.lightStratify);
  EXPECT_EQ(s.path.nextEvent, NextEvent::Off);
  EXPECT_FALSE(s.path.russianRoulette);
  EXPECT_EQ(s.path.sampling, Sampling::Hemisphere);
  EXPECT_EQ(s.path.gamma, 1.0);
  EXPECT_EQ(s.maxDepth, 5);
  EXPECT_TRUE(s.quadLights.empty());
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].brdf, BrdfModel::Phong);
  EXPECT_EQ(s.materials[0].roughness, 0.0);
  EXPECT_EQ(s.materials[0].quadLight, -1);
}

TEST(ParsePath, EverySettingIsRead) {
  SceneDesc s = parseBodyStrict(
      "integrator pathtracer\nspp 256\nlightsamples 16\nlightstratify on\nnexteventestimation mis\n"
      "russianroulette on\nimportancesampling brdf\ngamma 2.2\nmaxdepth -1\n");
  EXPECT_EQ(s.path.integrator, Integrator::PathTracer);
  EXPECT_EQ(s.path.spp, 256);
  EXPECT_EQ(s.path.lightSamples, 16);
  EXPECT_TRUE(s.path.lightStratify);
  EXPECT_EQ(s.path.nextEvent, NextEvent::Mis);
  EXPECT_TRUE(s.path.russianRoulette);
  EXPECT_EQ(s.path.sampling, Sampling::Brdf);
  EXPECT_EQ(s.path.gamma, 2.2);
  EXPECT_EQ(s.maxDepth, -1);
}

TEST(ParsePath, EveryKeywordValue) {
  EXPECT_EQ(parseBodyStrict("integrator raytracer\n").path.integrator, Integrator::Raytracer);
  EXPECT_EQ(parseBodyStrict("integrator analyticdirect\n").path.integrator, Integrator::AnalyticDirect);
  EXPECT_EQ(parseBodyStrict("integrator direct\n").path.integrator, Integrator::Direct);
  EXPECT_EQ(parseBodyStrict("integrator pathtracer\n").path.integrator, Integrator::PathTracer);
  const std::string pt = "integrator pathtracer\n";
  EXPECT_EQ(parseBodyStrict(pt + "nexteventestimation off\n").path.nextEvent, NextEvent::Off);
  EXPECT_EQ(parseBodyStrict(pt + "nexteventestimation on\n").path.nextEvent, NextEvent::On);
  EXPECT_EQ(parseBodyStrict(pt + "nexteventestimation mis\n").path.nextEvent, NextEvent::Mis);
  EXPECT_EQ(parseBodyStrict(pt + "importancesampling hemisphere\n").path.sampling, Sampling::Hemisphere);
  EXPECT_EQ(parseBodyStrict(pt + "importancesampling cosine\n").path.sampling, Sampling::Cosine);
  EXPECT_EQ(parseBodyStrict(pt + "importancesampling brdf\n").path.sampling, Sampling::Brdf);
  EXPECT_TRUE(parseBodyStrict(pt + "russianroulette on\n").path.russianRoulette);
  // Given twice, the last one counts (with a warning: parse_warnings_test.cpp, RepeatedSpp).
  EXPECT_FALSE(parseBody(pt + "russianroulette on\nrussianroulette off\n").path.russianRoulette);
  EXPECT_FALSE(parseBody(pt + "lightstratify on\nlightstratify off\nlightsamples 3\n").path.lightStratify);
  EXPECT_EQ(parseBodyStrict(pt + "brdf ggx\nsphere 0 0 0 1\n").materials[0].brdf, BrdfModel::Ggx);
  EXPECT_EQ(parseBodyStrict(pt + "brdf ggx\nbrdf phong\nsphere 0 0 0 1\n").materials[0].brdf, BrdfModel::Phong);
}

// `maxdepth -1` is no limit, for every integrator but the Whitted one, whichever line comes
// first; a later maxdepth replaces it.
TEST(ParsePath, UnlimitedDepthForThePathIntegrators) {
  EXPECT_EQ(parseBodyStrict("maxdepth -1\nintegrator pathtracer\nrussianroulette on\n").maxDepth, -1);
  EXPECT_EQ(parseBodyStrict("integrator direct\nmaxdepth -1\n").maxDepth, -1);
  EXPECT_EQ(parseBodyStrict("integrator analyticdirect\nmaxdepth -1\n").maxDepth, -1);
  EXPECT_EQ(parseBodyStrict("maxdepth 0\nintegrator pathtracer\n").maxDepth, 0);
  EXPECT_EQ(parseBody("maxdepth -1\nmaxdepth 3\n").maxDepth, 3);   // raytracer: fine
}

// `brdf` and `roughness` are material state, captured per object like `diffuse`.
TEST(ParsePath, BrdfAndRoughnessAreCapturedPerObject) {
  SceneDesc s = parseBodyStrict(
      "integrator pathtracer\nbrdf ggx\nroughness 0.25\nsphere 0 0 0 1\nroughness 0.5\nsphere 1 0 0 1\n"
      "brdf phong\nsphere 2 0 0 1\n");
  ASSERT_EQ(s.spheres.size(), 3u);
  const Material& a = s.materials[s.spheres[0].material];
  const Material& b = s.materials[s.spheres[1].material];
  const Material& c = s.materials[s.spheres[2].material];
  EXPECT_EQ(a.brdf, BrdfModel::Ggx);
  EXPECT_EQ(a.roughness, 0.25);
  EXPECT_EQ(b.brdf, BrdfModel::Ggx);
  EXPECT_EQ(b.roughness, 0.5);
  EXPECT_EQ(c.brdf, BrdfModel::Phong);
  EXPECT_EQ(c.roughness, 0.5);
  EXPECT_EQ(a.quadLight, -1);
}

TEST(ParsePath, QuadLightIsALightAndTwoTriangles) {
  SceneDesc s = parseBodyStrict("integrator direct\ndiffuse 1 0 0\nquadLight -1 1 -1  0 0 2  2 0 0  5 4 3\n");
  ASSERT_EQ(s.quadLights.size(), 1u);
  const QuadLight& q = s.quadLights[0];
  EXPECT_EQ(q.a, dvec3(-1, 1, -1));
  EXPECT_EQ(q.ab, dvec3(0, 0, 2));
  EXPECT_EQ(q.ac, dvec3(2, 0, 0));
  EXPECT_EQ(q.radiance, dvec3(5, 4, 3));
  EXPECT_EQ(q.line, 5);
  ASSERT_EQ(s.triangles.size(), 2u);
  expectQuadGeometry(s, 0);
  // The course's light faces down, onto its subject: cross(ac, ab) = (0, -4, 0).
  expectNear(faceNormal(s.triangles[0]), dvec3(0, -1, 0));
  expectNear(faceNormal(s.triangles[1]), dvec3(0, -1, 0));
  // The current material does not leak into the light's.
  EXPECT_EQ(s.materials[s.triangles[0].material].diffuse, dvec3(0.0));
}

// Corners by the current transform: a as a point, ab and ac as differences of transformed
// corners; the normal follows the transformed sides, also under a mirroring scale.
TEST(ParsePath, QuadLightUnderATransform) {
  SceneDesc s = parseBodyStrict(
      "integrator pathtracer\npushTransform\ntranslate 1 2 3\nrotate 0 0 1 90\nscale 2 3 4\n"
      "quadLight 1 0 0  0 1 0  0 0 1  7 7 7\npopTransform\nscale -1 1 1\nquadLight 0 0 0  1 0 0  0 1 0  1 1 1\n"
      "quadLight 0 5 0  1 0 0  0 1 0  2 2 2\n");
  ASSERT_EQ(s.quadLights.size(), 3u);
  dmat4 m = glm::scale(glm::rotate(glm::translate(dmat4(1.0), dvec3(1, 2, 3)), glm::radians(90.0), dvec3(0, 0, 1)),
                       dvec3(2, 3, 4));
  auto point = [&](dvec3 p) { return dvec3(m * glm::dvec4(p, 1.0)); };
  const QuadLight& q = s.quadLights[0];
  expectNear(q.a, point({1, 0, 0}));
  expectNear(q.a, dvec3(1, 4, 3));
  expectNear(q.ab, point({1, 1, 0}) - point({1, 0, 0}));
  expectNear(q.ab, dvec3(-3, 0, 0));
  expectNear(q.ac, dvec3(0, 0, 4));
  EXPECT_EQ(q.radiance, dvec3(7, 7, 7));
  for (int i = 0; i < 3; ++i) expectQuadGeometry(s, i);
  // cross(ac, ab) = cross((0,0,4), (-3,0,0)) = (0, -12, 0).
  for (const Triangle& t : trianglesOfQuadLight(s, 0)) expectNear(faceNormal(t), dvec3(0, -1, 0));
  // Mirrored: ab = (-1, 0, 0), ac = (0, 1, 0); cross(ac, ab) = (0, 0, 1).
  expectNear(s.quadLights[1].ab, dvec3(-1, 0, 0));
  for (const Triangle& t : trianglesOfQuadLight(s, 1)) expectNear(faceNormal(t), dvec3(0, 0, 1));
  // Each quad light has its own material and index.
  ASSERT_EQ(trianglesOfQuadLight(s, 1).size(), 2u);
  ASSERT_EQ(trianglesOfQuadLight(s, 2).size(), 2u);
  EXPECT_NE(trianglesOfQuadLight(s, 1)[0].material, trianglesOfQuadLight(s, 2)[0].material);
  EXPECT_EQ(s.materials[trianglesOfQuadLight(s, 2)[0].material].emission, dvec3(2, 2, 2));
  EXPECT_EQ(s.triangles.size(), 6u);
}

// The integrator may come after the quad light; the light's material does not split the
// material of the objects around it.
TEST(ParsePath, IntegratorAfterQuadLight) {
  SceneDesc s = parseBodyStrict(
      "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\ndiffuse 0.5 0.5 0.5\ntri 0 1 2\n"
      "quadLight 0 2 0  1 0 0  0 0 1  1 1 1\ntri 0 2 1\nintegrator analyticdirect\n");
  ASSERT_EQ(s.quadLights.size(), 1u);
  ASSERT_EQ(s.triangles.size(), 4u);
  expectQuadGeometry(s, 0);
  std::vector<std::uint32_t> objectMaterials;
  for (const Triangle& t : s.triangles)
    if (s.materials[t.material].quadLight < 0) objectMaterials.push_back(t.material);
  ASSERT_EQ(objectMaterials.size(), 2u);
  EXPECT_EQ(objectMaterials[0], objectMaterials[1]);
  EXPECT_EQ(s.materials[objectMaterials[0]].diffuse, dvec3(0.5));
}

// The course's 16 scenes: no warning, even with --strict, and the settings they say.
struct CourseSettings {
  const char* file;
  Integrator integrator;
  int spp, lightSamples;
  bool stratify;
  NextEvent nextEvent;
  bool russianRoulette;
  Sampling sampling;
  double gamma;
  int maxDepth;
  std::size_t quadLights, spheres;
};

void PrintTo(const CourseSettings& c, std::ostream* os) { *os << c.file; }

class Cse168Scene : public ::testing::TestWithParam<CourseSettings> {};

constexpr auto kA = Integrator::AnalyticDirect, kD = Integrator::Direct, kP = Integrator::PathTracer;
constexpr auto kOff = NextEvent::Off, kOn = NextEvent::On, kMis = NextEvent::Mis;
constexpr auto kHemi = Sampling::Hemisphere, kCos = Sampling::Cosine, kBrdf = Sampling::Brdf;

const CourseSettings kCourseScenes[] = {
    {"hw2/analytic", kA, 1, 1, false, kOff, false, kHemi, 1.0, 5, 1, 0},
    {"hw2/cornell", kD, 1, 25, true, kOff, false, kHemi, 1.0, 5, 1, 1},
    {"hw2/direct3x3", kD, 1, 9, true, kOff, false, kHemi, 1.0, 5, 1, 0},
    {"hw2/direct9", kD, 1, 9, false, kOff, false, kHemi, 1.0, 5, 1, 0},
    {"hw2/dragon", kD, 1, 25, true, kOff, false, kHemi, 1.0, 5, 2, 0},
    {"hw2/sphere", kD, 1, 25, true, kOff, false, kHemi, 1.0, 5, 3, 1},
    {"hw3/cornellNEE", kP, 64, 1, false, kOn, false, kHemi, 1.0, 5, 1, 1},
    {"hw3/cornellRR", kP, 64, 1, false, kOn, true, kHemi, 1.0, -1, 1, 1},
    {"hw3/cornellSimple", kP, 64, 1, false, kOff, false, kHemi, 1.0, 5, 1, 1},
    {"hw3/dragon", kP, 64, 1, false, kOn, true, kHemi, 1.0, 5, 2, 0},
    {"hw4/cornellBRDF", kP, 64, 1, false, kOn, true, kBrdf, 1.0, -1, 1, 1},
    {"hw4/cornellCosine", kP, 64, 1, false, kOn, true, kCos, 1.0, -1, 1, 1},
    {"hw4/cornellMIS", kP, 64, 1, false, kMis, true, kBrdf, 1.0, -1, 1, 1},
    {"hw4/dragon", kP, 128, 1, false, kMis, true, kBrdf, 2.2, 5, 2, 0},
    {"hw4/ggx", kP, 64, 1, false, kOn, true, kBrdf, 2.2, -1, 2, 6},
    {"hw4/mis", kP, 32, 1, false, kMis, false, kBrdf, 2.2, 1, 5, 0},
};

ParsedScene parseCourseScene(const std::string& dir, const std::string& name) {
  return parseSceneFileWithWarnings(dir + "/scenes/" + name + ".test", ParseOptions{true});
}

TEST_P(Cse168Scene, ParsesWithNoWarningAndItsSettings) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  const CourseSettings& c = GetParam();
  ParsedScene p = parseCourseScene(*dir, c.file);
  EXPECT_TRUE(p.warnings.empty()) << p.warnings.front().format();
  const SceneDesc& s = p.scene;
  EXPECT_EQ(s.path.integrator, c.integrator);
  EXPECT_EQ(s.path.spp, c.spp);
  EXPECT_EQ(s.path.lightSamples, c.lightSamples);
  EXPECT_EQ(s.path.lightStratify, c.stratify);
  EXPECT_EQ(s.path.nextEvent, c.nextEvent);
  EXPECT_EQ(s.path.russianRoulette, c.russianRoulette);
  EXPECT_EQ(s.path.sampling, c.sampling);
  EXPECT_EQ(s.path.gamma, c.gamma);
  EXPECT_EQ(s.maxDepth, c.maxDepth);
  EXPECT_EQ(s.spheres.size(), c.spheres);
  ASSERT_EQ(s.quadLights.size(), c.quadLights);
  for (int i = 0; i < static_cast<int>(c.quadLights); ++i) expectQuadGeometry(s, i);
}

INSTANTIATE_TEST_SUITE_P(Cse168, Cse168Scene, ::testing::ValuesIn(kCourseScenes), [](const auto& p) {
  std::string name = p.param.file;
  for (char& ch : name)
    if (ch == '/') ch = '_';
  return name;
});

TEST(ParsePath, TheTableHoldsEveryCourseScene) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  std::size_t files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(*dir + "/scenes"))
    files += e.path().extension() == ".test";
  EXPECT_EQ(files, std::size(kCourseScenes));
}

// hw4/ggx.test: the six spheres' GGX roughness, in file order, and the floor and back wall
// with `brdf phong`.
TEST(ParsePath, CourseGgxRoughnessPerMaterial) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  SceneDesc s = parseCourseScene(*dir, "hw4/ggx").scene;
  const double roughness[] = {0.25, 0.05, 0.12, 0.01, 0.01, 0.7};
  ASSERT_EQ(s.spheres.size(), std::size(roughness));
  for (std::size_t i = 0; i < s.spheres.size(); ++i) {
    const Material& m = s.materials[s.spheres[i].material];
    EXPECT_EQ(m.brdf, BrdfModel::Ggx) << "sphere " << i;
    EXPECT_EQ(m.roughness, roughness[i]) << "sphere " << i;
  }
  for (const Triangle& t : s.triangles) {
    const Material& m = s.materials[t.material];
    if (m.quadLight >= 0) continue;
    EXPECT_EQ(m.brdf, BrdfModel::Phong);
    EXPECT_EQ(m.roughness, 1.0);
  }
}

// hw4/mis.test: four panel lights of equal power (L x area = 1, doc/path-tracing.md, "Quad lights"),
// and panels of GGX roughness 0.0005 to 0.15.
TEST(ParsePath, CourseMisLightsHaveEqualPower) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  SceneDesc s = parseCourseScene(*dir, "hw4/mis").scene;
  ASSERT_EQ(s.quadLights.size(), 5u);
  for (std::size_t i = 1; i < 5; ++i) {
    const QuadLight& q = s.quadLights[i];
    // The file rounds the sides and L (0.03333 x 0.03333 x 901.803 = 1.0018).
    EXPECT_NEAR(q.radiance.x * glm::length(glm::cross(q.ab, q.ac)), 1.0, 0.002) << "light " << i;
  }
  std::vector<double> ggx;
  for (const Triangle& t : s.triangles) {
    const Material& m = s.materials[t.material];
    if (m.brdf == BrdfModel::Ggx && (ggx.empty() || ggx.back() != m.roughness)) ggx.push_back(m.roughness);
  }
  EXPECT_EQ(ggx, (std::vector<double>{0.0005, 0.008, 0.07, 0.15}));
}

TEST(ParsePath, CourseDragonGamma) {
  auto dir = cse168Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse168Data);
  SceneDesc s = parseCourseScene(*dir, "hw4/dragon").scene;
  EXPECT_EQ(s.path.gamma, 2.2);
  EXPECT_EQ(s.triangles.size(), 100002u + 4u);
  std::size_t ggx = 0;
  for (const Triangle& t : s.triangles) ggx += s.materials[t.material].brdf == BrdfModel::Ggx;
  EXPECT_GT(ggx, 0u);
  EXPECT_EQ(s.materials[s.triangles[0].material].roughness, 0.1);
}
