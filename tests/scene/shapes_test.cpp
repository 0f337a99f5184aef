// Each shape's queries (host/scene/shapes/): its box holds the points it samples, its area
// against a closed form, its density integrates to 1 over its surface, its intersection and
// normal for rays whose answers are known, and the dispatch by primitive reference.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gpu_types.h"
#include "scene/shapes/shape.h"

namespace vkrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

Triangle makeTriangle(dvec3 a, dvec3 b, dvec3 c) {
  Triangle t;
  t.p[0] = a, t.p[1] = b, t.p[2] = c;
  return t;
}

Sphere makeSphere(const dmat4& worldFromObject, dvec3 center, double radius) {
  Sphere s;
  s.worldFromObject = worldFromObject;
  s.objectFromWorld = glm::inverse(worldFromObject);
  s.center = center;
  s.radius = radius;
  return s;
}

// A tilted triangle, and an ellipsoid: rotated, stretched unevenly, moved.
Triangle tiltedTriangle() { return makeTriangle({1.0, 0.5, -2.0}, {3.0, 1.0, -1.0}, {0.5, 2.5, 0.25}); }
Sphere ellipsoid() {
  dmat4 m = glm::translate(dmat4(1.0), dvec3(2.0, -1.0, 3.0));
  m = glm::rotate(m, 0.7, glm::normalize(dvec3(1.0, 2.0, -0.5)));
  m = glm::scale(m, dvec3(1.5, 0.5, 3.0));
  return makeSphere(m, dvec3(0.25, -0.5, 1.0), 0.75);
}

bool inBox(const dvec3& p, const dvec3& lo, const dvec3& hi) {
  const double slack = 1e-12 * (1.0 + glm::length(hi - lo));
  for (int a = 0; a < 3; ++a)
    if (p[a] < lo[a] - slack || p[a] > hi[a] + slack) return false;
  return true;
}

// The density of samplePoint per unit (u, v), pdf(x(u, v)) |dx/du x dx/dv|, averaged over
// the unit square (central differences, away from its edges, where sqrt(u) has no
// derivative): 1 when the area density is that of the sampler and integrates to 1.
template <class S>
double meanDensityTimesJacobian(const S& shape, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uniform(0.01, 0.99);
  constexpr double h = 1e-6;
  constexpr int kSamples = 20000;
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double u = uniform(rng), v = uniform(rng);
    const dvec3 du = (shapes::samplePoint(shape, u + h, v).x - shapes::samplePoint(shape, u - h, v).x) / (2.0 * h);
    const dvec3 dv = (shapes::samplePoint(shape, u, v + h).x - shapes::samplePoint(shape, u, v - h).x) / (2.0 * h);
    const SurfacePoint point = shapes::samplePoint(shape, u, v);
    sum += shapes::densityAt(shape, point.x).areaPdf * glm::length(glm::cross(du, dv));
  }
  return sum / kSamples;
}

TEST(Shapes, TriangleBoxHoldsItsSampledPoints) {
  const Triangle t = tiltedTriangle();
  dvec3 lo, hi;
  shapes::bounds(t, lo, hi);
  EXPECT_EQ(lo, dvec3(0.5, 0.5, -2.0));
  EXPECT_EQ(hi, dvec3(3.0, 2.5, 0.25));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) ASSERT_TRUE(inBox(shapes::samplePoint(t, uniform(rng), uniform(rng)).x, lo, hi));
}

TEST(Shapes, SphereBoxHoldsItsSampledPointsAndTouchesThem) {
  const Sphere s = ellipsoid();
  dvec3 lo, hi;
  shapes::bounds(s, lo, hi);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  dvec3 seenLo(kInfinity), seenHi(-kInfinity);
  for (int i = 0; i < 20000; ++i) {
    const dvec3 x = shapes::samplePoint(s, uniform(rng), uniform(rng)).x;
    ASSERT_TRUE(inBox(x, lo, hi));
    seenLo = glm::min(seenLo, x);
    seenHi = glm::max(seenHi, x);
  }
  // The box is the ellipsoid's own (exact), not merely one around it.
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(seenLo[a], lo[a], 0.02 * (hi[a] - lo[a])) << a;
    EXPECT_NEAR(seenHi[a], hi[a], 0.02 * (hi[a] - lo[a])) << a;
  }
}

TEST(Shapes, AreasAgainstClosedForms) {
  EXPECT_DOUBLE_EQ(shapes::area(makeTriangle({0, 0, 0}, {3, 0, 0}, {0, 4, 0})), 6.0);
  EXPECT_DOUBLE_EQ(shapes::area(tiltedTriangle()),
                   0.5 * glm::length(glm::cross(dvec3(2.0, 0.5, 1.0), dvec3(-0.5, 2.0, 2.25))));
  // A sphere under a similarity (rotation, uniform scale 2, translation): 4 pi (2 r)^2.
  dmat4 m = glm::translate(dmat4(1.0), dvec3(1.0, 2.0, 3.0));
  m = glm::rotate(m, 1.1, dvec3(0.0, 0.0, 1.0));
  m = glm::scale(m, dvec3(2.0));
  EXPECT_NEAR(shapes::area(makeSphere(m, dvec3(0.5, 0.0, 0.0), 1.5)), 4.0 * kPi * 9.0, 1e-12 * 4.0 * kPi * 9.0);
}

TEST(Shapes, DensitiesIntegrateToOne) {
  std::mt19937_64 rng(3);
  EXPECT_NEAR(meanDensityTimesJacobian(tiltedTriangle(), rng), 1.0, 1e-4);
  EXPECT_NEAR(meanDensityTimesJacobian(ellipsoid(), rng), 1.0, 1e-4);
  // Uniform in area where the area is known: the density is 1 / area at every point.
  const Triangle t = tiltedTriangle();
  EXPECT_NEAR(shapes::densityAt(t, t.p[0]).areaPdf * shapes::area(t), 1.0, 1e-12);
  const Sphere round = makeSphere(glm::scale(dmat4(1.0), dvec3(3.0)), dvec3(0.0), 1.0);
  EXPECT_NEAR(shapes::densityAt(round, dvec3(0.0, 3.0, 0.0)).areaPdf * shapes::area(round), 1.0, 1e-12);
}

TEST(Shapes, TriangleIntersectionOfKnownRays) {
  const Triangle t = makeTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  Hit hit;
  ASSERT_TRUE(shapes::intersect(t, {{0.25, 0.5, 2.0}, {0.0, 0.0, -1.0}}, 0.0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 2.0);
  EXPECT_DOUBLE_EQ(hit.b1, 0.25);
  EXPECT_DOUBLE_EQ(hit.b2, 0.5);
  EXPECT_EQ(shapes::normalAt(t, hit, dvec3(0.25, 0.5, 0.0)), dvec3(0.0, 0.0, 1.0));
  Hit miss;
  EXPECT_FALSE(shapes::intersect(t, {{0.75, 0.5, 2.0}, {0.0, 0.0, -1.0}}, 0.0, kInfinity, miss)) << "beyond the hypotenuse";
  EXPECT_FALSE(shapes::intersect(t, {{0.25, 0.5, 2.0}, {0.0, 0.0, -1.0}}, 0.0, 1.5, miss)) << "beyond tMax";
  EXPECT_FALSE(shapes::intersect(t, {{0.25, 0.5, 2.0}, {1.0, 0.0, 0.0}}, 0.0, kInfinity, miss)) << "parallel";
}

TEST(Shapes, SphereIntersectionOfKnownRays) {
  // Radius 1 at (0, 0, -5), scaled by 2 about the origin: radius 2 at (0, 0, -10).
  const Sphere s = makeSphere(glm::scale(dmat4(1.0), dvec3(2.0)), dvec3(0.0, 0.0, -5.0), 1.0);
  Hit hit;
  ASSERT_TRUE(shapes::intersect(s, {{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}}, 0.0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 8.0);
  EXPECT_EQ(shapes::normalAt(s, hit, dvec3(0.0, 0.0, -8.0)), dvec3(0.0, 0.0, 1.0));
  ASSERT_TRUE(shapes::intersect(s, {{0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}}, 9.0, kInfinity, hit)) << "the far side";
  EXPECT_DOUBLE_EQ(hit.t, 12.0);
  Hit miss;
  EXPECT_FALSE(shapes::intersect(s, {{2.5, 0.0, 0.0}, {0.0, 0.0, -1.0}}, 0.0, kInfinity, miss));
}

TEST(Shapes, DegenerateShapesAreNeverHit) {
  EXPECT_FALSE(shapes::neverHit(tiltedTriangle()));
  EXPECT_TRUE(shapes::neverHit(makeTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2})));
  EXPECT_FALSE(shapes::neverHit(ellipsoid()));
  EXPECT_TRUE(shapes::neverHit(makeSphere(dmat4(1.0), dvec3(0.0), 0.0)));
  Sphere flat = makeSphere(dmat4(1.0), dvec3(0.0), 1.0);
  flat.worldFromObject = glm::scale(dmat4(1.0), dvec3(1.0, 0.0, 1.0));
  EXPECT_TRUE(shapes::neverHit(flat));
}

TEST(Shapes, DispatchByPrimitiveReference) {
  SceneDesc scene;
  scene.triangles = {tiltedTriangle(), makeTriangle({0, 0, 0}, {3, 0, 0}, {0, 4, 0})};
  scene.triangles[1].material = 4;
  scene.spheres = {ellipsoid()};
  scene.spheres[0].material = 7;
  EXPECT_EQ(shapes::count(scene, gpu::kPrimTriangle), 2u);
  EXPECT_EQ(shapes::count(scene, gpu::kPrimSphere), 1u);
  const std::uint32_t triangle = gpu::primRef(gpu::kPrimTriangle, 1), sphere = gpu::primRef(gpu::kPrimSphere, 0);
  EXPECT_EQ(shapes::area(scene, triangle), 6.0);
  EXPECT_EQ(shapes::material(scene, triangle), 4u);
  EXPECT_EQ(shapes::material(scene, sphere), 7u);
  dvec3 lo, hi, ownLo, ownHi;
  shapes::bounds(scene, sphere, lo, hi);
  shapes::bounds(scene.spheres[0], ownLo, ownHi);
  EXPECT_EQ(lo, ownLo);
  EXPECT_EQ(hi, ownHi);
  EXPECT_EQ(shapes::samplePoint(scene, sphere, 0.3, 0.6).x, shapes::samplePoint(scene.spheres[0], 0.3, 0.6).x);
}

}  // namespace
}  // namespace vkrt
