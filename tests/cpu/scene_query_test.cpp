// The CPU backends' ray queries (host/cpu/scene_query.h): nearest and any hit through the BVH
// against hand-computed t and against a brute-force closed form over generated scenes, the
// surface normal and material at a hit, and the camera ray's directions.
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "cpu/scene_query.h"
#include "gpu_types.h"
#include "path_scenes.h"
#include "scene/bvh.h"
#include "test_support.h"

namespace vkrt {
namespace {

using test::expectNear;

constexpr double kPi = 3.14159265358979323846;

Sphere sphere(dvec3 c, double r, std::uint32_t material = 0) {
  Sphere s;
  s.center = c;
  s.radius = r;
  s.material = material;
  return s;
}

Triangle triangle(dvec3 a, dvec3 b, dvec3 c, std::uint32_t material = 0) {
  Triangle t;
  t.p[0] = a, t.p[1] = b, t.p[2] = c;
  t.material = material;
  return t;
}

// A scene with two materials, a 40x30 image and a camera at the origin looking down -z.
SceneDesc baseScene() {
  SceneDesc s;
  test::addMaterial(s, Material{});
  test::addMaterial(s, Material{});
  test::setCamera(s, dvec3(0.0), dvec3(0, 0, -1), 60.0, 40, 30);
  return s;
}

// The nearest t > tMin of a ray at a sphere, by the quadratic formula; +inf when it misses.
double sphereT(const Ray& r, dvec3 c, double radius, double tMin) {
  const dvec3 oc = r.origin - c;
  const double b = glm::dot(oc, r.dir), cc = glm::dot(oc, oc) - radius * radius;
  const double disc = b * b - cc;
  if (disc < 0.0) return INFINITY;
  const double q = std::sqrt(disc);
  for (double t : {-b - q, -b + q})
    if (t > tMin) return t;
  return INFINITY;
}

TEST(SceneQuery, RaysAtASphereHitWhereTheQuadraticSays) {
  SceneDesc s = baseScene();
  s.spheres.push_back(sphere(dvec3(0, 0, -5), 1.0, 1));
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  Hit hit;
  ASSERT_TRUE(q.intersect({dvec3(0.0), dvec3(0, 0, -1)}, 0.0, INFINITY, false, hit));
  EXPECT_NEAR(hit.t, 4.0, 1e-12);
  EXPECT_EQ(hit.prim, gpu::primRef(gpu::kPrimSphere, 0));
  // Off axis by 0.6: the chord's half is 0.8, t = 5 - 0.8, and the normal is (0, 0.6, 0.8).
  const Ray r{dvec3(0, 0.6, 0), dvec3(0, 0, -1)};
  ASSERT_TRUE(q.intersect(r, 0.0, INFINITY, false, hit));
  EXPECT_NEAR(hit.t, 4.2, 1e-12);
  dvec3 n;
  EXPECT_EQ(q.surfaceAt(hit, r.origin + hit.t * r.dir, n), 1u);
  expectNear(n, dvec3(0, 0.6, 0.8), 1e-12);
  // Past the sphere's edge: no hit.
  EXPECT_FALSE(q.intersect({dvec3(0, 1.01, 0), dvec3(0, 0, -1)}, 0.0, INFINITY, false, hit));
}

TEST(SceneQuery, TheIntervalIsOpenAndTheNormalIsNeverFlipped) {
  SceneDesc s = baseScene();
  s.spheres.push_back(sphere(dvec3(0, 0, -5), 1.0));
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  const Ray r{dvec3(0.0), dvec3(0, 0, -1)};
  Hit hit;
  EXPECT_FALSE(q.intersect(r, 0.0, 3.9, false, hit));   // before the sphere
  ASSERT_TRUE(q.intersect(r, 4.5, INFINITY, false, hit));   // past the near side: the far one
  EXPECT_NEAR(hit.t, 6.0, 1e-12);
  // From inside, the normal at the far side still points out of the sphere, along the ray.
  dvec3 n;
  q.surfaceAt(hit, r.origin + hit.t * r.dir, n);
  expectNear(n, dvec3(0, 0, -1), 1e-12);
  EXPECT_FALSE(q.intersect(r, 6.5, INFINITY, false, hit));
}

TEST(SceneQuery, ARayAtATriangleHitsItsPlaneWithItsBarycentrics) {
  SceneDesc s = baseScene();
  // In the plane z = -3: p0 = (-1, -1), p1 = (2, -1), p2 = (-1, 2).
  s.triangles.push_back(triangle(dvec3(-1, -1, -3), dvec3(2, -1, -3), dvec3(-1, 2, -3), 1));
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  // Through (0.2, 0.3, -3): x = -1 + 3 b1, y = -1 + 3 b2, so b1 = 0.4, b2 = 1.3 / 3.
  const dvec3 target(0.2, 0.3, -3.0);
  const Ray r{dvec3(0.0), glm::normalize(target)};
  Hit hit;
  ASSERT_TRUE(q.intersect(r, 0.0, INFINITY, false, hit));
  EXPECT_NEAR(hit.t, glm::length(target), 1e-12);
  EXPECT_EQ(hit.prim, gpu::primRef(gpu::kPrimTriangle, 0));
  EXPECT_NEAR(hit.b1, 0.4, 1e-12);
  EXPECT_NEAR(hit.b2, 1.3 / 3.0, 1e-12);
  dvec3 n;
  EXPECT_EQ(q.surfaceAt(hit, r.origin + hit.t * r.dir, n), 1u);
  expectNear(n, dvec3(0, 0, 1), 1e-12);   // cross(p1 - p0, p2 - p0), toward the camera here
  // Beside it (x + y > 1 is past the hypotenuse): a miss.
  EXPECT_FALSE(q.intersect({dvec3(0.0), glm::normalize(dvec3(0.6, 0.6, -3.0))}, 0.0, INFINITY, false, hit));
}

TEST(SceneQuery, AnEllipsoidsNormalIsItsImplicitGradient) {
  SceneDesc s = baseScene();
  Sphere e = sphere(dvec3(0.0), 1.0);
  e.worldFromObject = glm::scale(glm::translate(dmat4(1.0), dvec3(0, 0, -10)), dvec3(2, 1, 1));
  e.objectFromWorld = glm::inverse(e.worldFromObject);
  s.spheres.push_back(e);
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  // x^2/4 + y^2 + z^2 = 1 about (0, 0, -10); at (sqrt 2, sqrt 0.5, 0) its gradient is
  // (x/2, 2y, 2z), along (sqrt 2 / 4, sqrt 0.5, 0).
  const dvec3 p(std::sqrt(2.0), std::sqrt(0.5), -10.0);
  const dvec3 expected = glm::normalize(dvec3(std::sqrt(2.0) / 4.0, std::sqrt(0.5), 0.0));
  const Ray r{p + 3.0 * expected, -expected};
  Hit hit;
  ASSERT_TRUE(q.intersect(r, 0.0, INFINITY, false, hit));
  EXPECT_NEAR(hit.t, 3.0, 1e-9);
  dvec3 n;
  q.surfaceAt(hit, r.origin + hit.t * r.dir, n);
  expectNear(n, expected, 1e-9);
}

TEST(SceneQuery, NearestAndAnyHitAgreeWithBruteForceOverGeneratedScenes) {
  std::mt19937 rng(168);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    SceneDesc s = baseScene();
    struct Ball { dvec3 c; double r; };
    std::vector<Ball> balls;
    const int count = 20 + 60 * trial;
    for (int i = 0; i < count; ++i) {
      const Ball b{dvec3(u(rng), u(rng), u(rng)) * 10.0, 0.2 + 0.5 * std::abs(u(rng))};
      balls.push_back(b);
      s.spheres.push_back(sphere(b.c, b.r, static_cast<std::uint32_t>(i % 2)));
    }
    const Bvh bvh = buildBvh(s);
    const SceneQuery q(s, bvh);
    int hits = 0;
    for (int k = 0; k < 300; ++k) {
      // Every other ray aimed at a sphere's centre, so that some surely hit.
      const dvec3 origin = dvec3(u(rng), u(rng), u(rng)) * 12.0;
      const dvec3 toward = k % 2 ? balls[static_cast<std::size_t>(k) % balls.size()].c - origin
                                 : dvec3(u(rng), u(rng), u(rng));
      const Ray r{origin, glm::normalize(toward)};
      const double tMin = 1e-6;
      double best = INFINITY;
      int bestIndex = -1;
      for (int i = 0; i < count; ++i) {
        const double t = sphereT(r, balls[i].c, balls[i].r, tMin);
        if (t < best) best = t, bestIndex = i;
      }
      Hit hit;
      const bool found = q.intersect(r, tMin, INFINITY, false, hit);
      Hit any;
      const bool foundAny = q.intersect(r, tMin, INFINITY, true, any);
      ASSERT_EQ(found, bestIndex >= 0) << "trial " << trial << ", ray " << k;
      ASSERT_EQ(foundAny, found) << "trial " << trial << ", ray " << k;
      if (!found) continue;
      ++hits;
      EXPECT_NEAR(hit.t, best, 1e-9 * (1.0 + best)) << "trial " << trial << ", ray " << k;
      EXPECT_EQ(hit.prim, gpu::primRef(gpu::kPrimSphere, static_cast<std::uint32_t>(bestIndex)));
      // Any hit: some sphere's own t along this ray, within the interval.
      const std::uint32_t i = gpu::primIndex(any.prim);
      ASSERT_LT(i, static_cast<std::uint32_t>(count));
      EXPECT_GE(any.t, best - 1e-9 * (1.0 + best));
      EXPECT_GT(any.t, tMin);
      EXPECT_NEAR(any.t, sphereT(r, balls[i].c, balls[i].r, tMin), 1e-9 * (1.0 + any.t))
          << "trial " << trial << ", ray " << k;
      // Below the nearest hit's t nothing is found.
      Hit none;
      EXPECT_FALSE(q.intersect(r, tMin, best * (1.0 - 1e-9), false, none)) << "trial " << trial << ", ray " << k;
    }
    EXPECT_GE(hits, 150) << "trial " << trial;   // the rays do meet the spheres
  }
}

TEST(SceneQuery, AnEmptySceneIsNeverHit) {
  SceneDesc s = baseScene();
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  Hit hit;
  EXPECT_FALSE(q.intersect({dvec3(0.0), dvec3(0, 0, -1)}, 0.0, INFINITY, false, hit));
  EXPECT_FALSE(q.intersect({dvec3(0.0), dvec3(0, 0, -1)}, 0.0, INFINITY, true, hit));
}

TEST(SceneQuery, CameraRaysSpanTheFieldOfView) {
  SceneDesc s = baseScene();   // 40x30, fovy 60, at the origin looking down -z, up +y
  s.camera.from = dvec3(1, 2, 3);
  s.camera.at = dvec3(1, 2, -7);
  const Bvh bvh = buildBvh(s);
  const SceneQuery q(s, bvh);
  const double tanY = std::tan(kPi / 6.0), tanX = tanY * 40.0 / 30.0;
  auto expectDir = [&](double px, double py, dvec3 d) {
    const Ray r = q.cameraRay(px, py);
    expectNear(r.origin, s.camera.from, 0.0);
    expectNear(r.dir, glm::normalize(d), 1e-12);
  };
  expectDir(20, 15, dvec3(0, 0, -1));            // the centre looks at `at`
  expectDir(20, 0, dvec3(0, tanY, -1));          // the top edge: half of fovy up
  expectDir(20, 30, dvec3(0, -tanY, -1));
  expectDir(0, 15, dvec3(-tanX, 0, -1));         // the left edge: -x, the aspect ratio wider
  expectDir(40, 0, dvec3(tanX, tanY, -1));
  expectDir(30, 22.5, dvec3(tanX / 2, -tanY / 2, -1));
}

}  // namespace
}  // namespace vkrt
