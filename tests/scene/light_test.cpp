// The point and directional lights (host/scene/light.h): what reaches a point, against the
// closed forms of doc/scene-format.md, "Shading"; the GPU layout in the float32 frame,
// against the frame's own map; the strongest arrival, against a sweep of distances.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "scene/light.h"

namespace vkrt {
namespace {

using glm::dvec3;

Light pointLight(dvec3 position, dvec3 attenuation) {
  Light l;
  l.type = LightType::Point;
  l.vec = position;
  l.color = {2.0, 3.0, 4.0};
  l.attenuation = attenuation;
  return l;
}

TEST(Light, PointLightArrivesAlongTheLineWithItsAttenuation) {
  const Light l = pointLight({1.0, 2.0, 3.0}, {0.5, 0.25, 0.125});
  LightArrival a;
  ASSERT_TRUE(arrivalAt(l, {1.0, 2.0, -1.0}, a));   // 4 below the light
  EXPECT_EQ(a.toLight, dvec3(0.0, 0.0, 1.0));
  EXPECT_EQ(a.distance, 4.0);
  EXPECT_EQ(a.divisor, 0.5 + 0.25 * 4.0 + 0.125 * 16.0);
}

TEST(Light, PointLightLightsNothingWhereItIs) {
  LightArrival a;
  EXPECT_FALSE(arrivalAt(pointLight({1.0, 2.0, 3.0}, {1.0, 0.0, 0.0}), {1.0, 2.0, 3.0}, a));
}

TEST(Light, PointLightFarBeyondDoubleSquaresStillHasADistance) {
  LightArrival a;
  ASSERT_TRUE(arrivalAt(pointLight({3e300, 0.0, 4e300}, {1.0, 0.0, 0.0}), {0.0, 0.0, 0.0}, a));
  EXPECT_NEAR(a.distance / 5e300, 1.0, 1e-15);
  EXPECT_NEAR(a.toLight.x, 0.6, 1e-15);
  EXPECT_NEAR(a.toLight.z, 0.8, 1e-15);
}

TEST(Light, DirectionalLightArrivesFromEverywhereUnattenuated) {
  Light l;
  l.type = LightType::Directional;
  l.vec = {0.0, 0.6, 0.8};
  l.attenuation = {5.0, 5.0, 5.0};   // never used by a directional light
  for (dvec3 p : {dvec3(0.0), dvec3(1e6, -3.0, 2.0)}) {
    LightArrival a;
    ASSERT_TRUE(arrivalAt(l, p, a));
    EXPECT_EQ(a.toLight, l.vec);
    EXPECT_EQ(a.distance, std::numeric_limits<double>::infinity());
    EXPECT_EQ(a.divisor, 1.0);
  }
}

TEST(Light, GpuLayoutIsInTheFloatFrame) {
  const Light l = pointLight({5.0, 6.0, 7.0}, {1.0, 0.5, 0.25});
  const gpu::GpuLight g = toGpu(l, {1.0, 2.0, 3.0}, 0.5);
  EXPECT_EQ(g.positionOrDirection.x, 2.0f);
  EXPECT_EQ(g.positionOrDirection.y, 2.0f);
  EXPECT_EQ(g.positionOrDirection.z, 2.0f);
  EXPECT_EQ(g.kind, gpu::kLightPoint);
  // The divisor in frame units (world units times the scale): c0, c1 / scale, c2 / scale^2.
  EXPECT_EQ(g.attenuation0, 1.0f);
  EXPECT_EQ(g.attenuation1, 1.0f);
  EXPECT_EQ(g.attenuation2, 1.0f);
  EXPECT_EQ(g.color.y, 3.0f);

  Light d;
  d.type = LightType::Directional;
  d.vec = {0.0, 0.0, 1.0};
  d.attenuation = {5.0, 5.0, 5.0};   // (a directional light has none)
  const gpu::GpuLight gd = toGpu(d, {100.0, 0.0, 0.0}, 0.25);   // directions do not move or scale
  EXPECT_EQ(gd.positionOrDirection.z, 1.0f);
  EXPECT_EQ(gd.kind, gpu::kLightDirectional);
  EXPECT_EQ(gd.attenuation0, 1.0f);   // no attenuation, whatever the scene said
  EXPECT_EQ(gd.attenuation1, 0.0f);
}

TEST(Light, AFarPointLightMovesNearerWithItsAttenuationInItsColour) {
  // 2^50 frame units away: beyond what float32 places; moved to 2^40 on the same line.
  const double far = 0x1p50;
  const Light l = pointLight({0.0, 0.0, far}, {1.0, 0.0, 1.0});
  const gpu::GpuLight g = toGpu(l, dvec3(0.0), 1.0);
  EXPECT_EQ(g.positionOrDirection.x, 0.0f);
  EXPECT_EQ(g.positionOrDirection.z, static_cast<float>(0x1p40));
  EXPECT_EQ(g.attenuation0, 1.0f);
  EXPECT_EQ(g.attenuation2, 0.0f);
  EXPECT_FLOAT_EQ(g.color.z, static_cast<float>(4.0 / (1.0 + far * far)));
}

TEST(Light, StrongestArrivalBoundsEveryDistance) {
  for (dvec3 att : {dvec3(1.0, 0.0, 0.0), dvec3(0.5, 2.0, 1.0), dvec3(2.0, 0.0, 3.0)}) {
    bool keepsSign = false;
    const double strongest = strongestDivisorInverse(pointLight(dvec3(0.0), att), keepsSign);
    EXPECT_TRUE(keepsSign);
    for (double r = 0.0; r < 100.0; r += 0.37) {
      LightArrival a;
      ASSERT_TRUE(arrivalAt(pointLight({r + 1e-9, 0.0, 0.0}, att), dvec3(0.0), a));
      EXPECT_LE(1.0 / a.divisor, strongest * (1.0 + 1e-12)) << "r " << r;
    }
  }
  bool keepsSign = true;
  EXPECT_EQ(strongestDivisorInverse(pointLight(dvec3(0.0), {0.0, 1.0, 0.0}), keepsSign),
            std::numeric_limits<double>::infinity());   // 1 / r near the light
  EXPECT_TRUE(keepsSign);
  strongestDivisorInverse(pointLight(dvec3(0.0), {1.0, -0.5, 0.0}), keepsSign);
  EXPECT_FALSE(keepsSign);
  Light d;
  EXPECT_EQ(strongestDivisorInverse(d, keepsSign), 1.0);
}

}  // namespace
}  // namespace vkrt
