// The emitter table (host/scene/emitters.h): which triangles and spheres are lights, in scene
// order, and pick probabilities proportional to area x sum|emission|, computed here from
// closed-form areas; the cdf rises to exactly 1; quad lights' materials are left out.
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gpu_types.h"
#include "path_scenes.h"
#include "scene/emitters.h"

namespace vkrt {
namespace {

using test::addMaterial;

constexpr double kPi = 3.14159265358979323846;

Material emitting(dvec3 e) {
  Material m;
  m.emission = e;
  return m;
}

Triangle triangle(dvec3 a, dvec3 b, dvec3 c, std::uint32_t material) {
  Triangle t;
  t.p[0] = a, t.p[1] = b, t.p[2] = c;
  t.material = material;
  return t;
}

// A sphere of radius r about c, under a rotation and a uniform scale s: a sphere of radius s r.
Sphere sphere(dvec3 c, double r, double s, std::uint32_t material) {
  Sphere sp;
  sp.worldFromObject = glm::scale(glm::rotate(glm::translate(dmat4(1.0), dvec3(1, -2, 3)), 0.7, dvec3(1, 1, 0)),
                                  dvec3(s));
  sp.objectFromWorld = glm::inverse(sp.worldFromObject);
  sp.center = c;
  sp.radius = r;
  sp.material = material;
  return sp;
}

void expectConsistent(const EmitterTable& t) {
  ASSERT_EQ(t.pick.size(), t.prims.size());
  ASSERT_EQ(t.cdf.size(), t.prims.size());
  double sum = 0.0;
  for (std::size_t e = 0; e < t.cdf.size(); ++e) {
    EXPECT_GT(t.pick[e], 0.0);
    sum += t.pick[e];
    EXPECT_NEAR(t.cdf[e], sum, 1e-12) << e;
    if (e > 0) {
      EXPECT_GE(t.cdf[e], t.cdf[e - 1]) << e;
    }
    EXPECT_LE(t.cdf[e], 1.0);
  }
  if (!t.cdf.empty()) {
    EXPECT_EQ(t.cdf.back(), 1.0);
  }
}

TEST(Emitters, RadianceWeightIsTheSumOfAbsoluteEmission) {
  EXPECT_EQ(emitterRadianceWeight(emitting(dvec3(0.0))), 0.0);
  EXPECT_EQ(emitterRadianceWeight(emitting(dvec3(1.0, 0.5, 0.25))), 1.75);
  EXPECT_EQ(emitterRadianceWeight(emitting(dvec3(-2.0, 0.0, 1.0))), 3.0);
  Material quad = emitting(dvec3(5.0));
  quad.quadLight = 0;
  EXPECT_EQ(emitterRadianceWeight(quad), 0.0);
}

TEST(Emitters, AnUnlitSceneHasNone) {
  SceneDesc scene;
  EXPECT_TRUE(collectEmitters(scene).prims.empty());
  const auto dark = addMaterial(scene, Material{});
  scene.triangles.push_back(triangle(dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), dark));
  scene.spheres.push_back(sphere(dvec3(0), 1.0, 1.0, dark));
  test::addQuadLight(scene, dvec3(0, 2, 0), dvec3(1, 0, 0), dvec3(0, 0, 1), dvec3(10.0));
  const EmitterTable t = collectEmitters(scene);
  EXPECT_TRUE(t.prims.empty());
  EXPECT_TRUE(t.cdf.empty());
  EXPECT_EQ(t.totalWeight, 0.0);
}

TEST(Emitters, PicksAreProportionalToAreaTimesEmission) {
  SceneDesc scene;
  const auto dark = addMaterial(scene, Material{});
  const auto warm = addMaterial(scene, emitting(dvec3(1.0, 0.5, 0.25)));   // weight 1.75 per unit area
  const auto odd = addMaterial(scene, emitting(dvec3(-2.0, 0.0, 1.0)));    // weight 3
  // The quad light comes first, so that its triangles are 0 and 1 and its material 3.
  test::addQuadLight(scene, dvec3(0, 5, 0), dvec3(2, 0, 0), dvec3(0, 0, 2), dvec3(100.0));
  scene.triangles.push_back(triangle(dvec3(0), dvec3(2, 0, 0), dvec3(0, 3, 0), warm));         // 2: area 3
  scene.triangles.push_back(triangle(dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), dark));         // 3: dark
  scene.triangles.push_back(triangle(dvec3(1, 1, 1), dvec3(1, 1, 5), dvec3(1, 4, 1), odd));    // 4: area 6
  scene.triangles.push_back(triangle(dvec3(0), dvec3(1, 1, 1), dvec3(2, 2, 2), warm));         // 5: area 0
  scene.triangles.push_back(triangle(dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), 99));           // 6: no material
  scene.spheres.push_back(sphere(dvec3(0.5, 0, 0), 2.0, 3.0, warm));   // 0: radius 6
  scene.spheres.push_back(sphere(dvec3(0), 1.0, 1.0, dark));           // 1: dark
  scene.spheres.push_back(sphere(dvec3(0), 0.5, 1.0, odd));            // 2: radius 0.5

  const double weights[] = {3.0 * 1.75, 6.0 * 3.0, 4 * kPi * 36.0 * 1.75, 4 * kPi * 0.25 * 3.0};
  const std::uint32_t prims[] = {gpu::primRef(gpu::kPrimTriangle, 2), gpu::primRef(gpu::kPrimTriangle, 4),
                                 gpu::primRef(gpu::kPrimSphere, 0), gpu::primRef(gpu::kPrimSphere, 2)};
  double total = 0.0;
  for (double w : weights) total += w;

  const EmitterTable t = collectEmitters(scene);
  ASSERT_EQ(t.prims.size(), 4u);
  expectConsistent(t);
  EXPECT_NEAR(t.totalWeight, total, 1e-9 * total);
  for (std::size_t e = 0; e < 4; ++e) {
    EXPECT_EQ(t.prims[e], prims[e]) << e;
    EXPECT_NEAR(t.pick[e], weights[e] / total, 1e-12) << e;
  }
}

TEST(Emitters, GeneratedScenesGiveACdfThatEndsAtOne) {
  std::mt19937 rng(167);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    SceneDesc scene;
    std::vector<double> perArea;
    const int materials = 1 + trial % 5;
    for (int m = 0; m < materials; ++m) {
      const dvec3 e = (m == 0 || u(rng) < -0.5) ? dvec3(0.0) : dvec3(u(rng), u(rng), u(rng)) * 4.0;
      addMaterial(scene, emitting(e));
      perArea.push_back(std::abs(e.x) + std::abs(e.y) + std::abs(e.z));
    }
    std::vector<double> expected;
    const int triangles = trial * 7 % 40;
    for (int i = 0; i < triangles; ++i) {
      const dvec3 a(u(rng), u(rng), u(rng)), ab(u(rng), u(rng), u(rng)), ac(u(rng), u(rng), u(rng));
      const auto m = static_cast<std::uint32_t>(i % materials);
      scene.triangles.push_back(triangle(a, a + ab, a + ac, m));
      const double w = 0.5 * glm::length(glm::cross(ab, ac)) * perArea[m];
      if (w > 0.0) expected.push_back(w);
    }
    const int spheres = trial % 6;
    for (int i = 0; i < spheres; ++i) {
      const double r = 0.1 + std::abs(u(rng)), s = 0.5 + std::abs(u(rng));
      const auto m = static_cast<std::uint32_t>((i + 1) % materials);
      scene.spheres.push_back(sphere(dvec3(u(rng), u(rng), u(rng)), r, s, m));
      const double w = 4 * kPi * (r * s) * (r * s) * perArea[m];
      if (w > 0.0) expected.push_back(w);
    }
    const EmitterTable t = collectEmitters(scene);
    ASSERT_EQ(t.prims.size(), expected.size()) << "trial " << trial;
    expectConsistent(t);
    double total = 0.0;
    for (double w : expected) total += w;
    for (std::size_t e = 0; e < expected.size(); ++e)
      EXPECT_NEAR(t.pick[e], expected[e] / total, 1e-9) << "trial " << trial << ", emitter " << e;
  }
}

}  // namespace
}  // namespace vkrt
