// The CPU path integrators' BRDFs and samplers: each sampler's density is the one it draws
// from. For a fixed w_o, the mean of f cos / pdf over a sampler's directions must equal the
// BRDF's albedo, integral of f cos over the hemisphere, computed here by quadrature; a pdf
// that is wrong anywhere the sampler goes biases that mean. z-tests, false alarm 1e-4 each
// for a seed drawn at random (deterministic for the fixed keys here).
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/path_brdf.h"
#include "gpu_types.h"

namespace vkrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The albedo by the midpoint rule in (cos theta, phi), which makes dw = d(cos) dphi exact.
dvec3 albedoByQuadrature(const Material& m, const dvec3& n, const dvec3& wo, int steps) {
  dvec3 t, b;
  frameAround(n, t, b);
  dvec3 sum(0.0);
  for (int i = 0; i < steps; ++i) {
    const double z = (i + 0.5) / steps, r = std::sqrt(1.0 - z * z);
    for (int j = 0; j < 2 * steps; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / (2 * steps);
      const dvec3 wi = r * std::cos(phi) * t + r * std::sin(phi) * b + z * n;
      sum += evalBrdf(m, n, wi, wo) * z;
    }
  }
  return sum * (2.0 * kPi / (static_cast<double>(steps) * 2 * steps));
}

Material glossy(BrdfModel model, double shininessOrRoughness) {
  Material m;
  m.diffuse = dvec3(0.3, 0.2, 0.1);
  m.specular = dvec3(0.5, 0.4, 0.6);
  m.brdf = model;
  if (model == BrdfModel::Phong) m.shininess = shininessOrRoughness;
  else m.roughness = shininessOrRoughness;
  return m;
}

TEST(PathBrdf, EverySamplerEstimatesTheAlbedoWithItsOwnPdf) {
  const dvec3 n = glm::normalize(dvec3(0.2, 1.0, -0.3));
  dvec3 t, b;
  frameAround(n, t, b);
  const Material materials[] = {glossy(BrdfModel::Phong, 5), glossy(BrdfModel::Phong, 30), glossy(BrdfModel::Ggx, 0.3),
                                glossy(BrdfModel::Ggx, 0.6)};
  std::uint32_t key = 0;
  for (const Material& m : materials)
    for (double cosO : {0.9, 0.4}) {
      const dvec3 wo = glm::normalize(cosO * n + std::sqrt(1 - cosO * cosO) * t);
      const dvec3 albedo = albedoByQuadrature(m, n, wo, 1200);
      for (Sampling sampling : {Sampling::Hemisphere, Sampling::Cosine, Sampling::Brdf}) {
        constexpr int kSamples = 200000;
        double sum = 0.0, squares = 0.0;   // channel 1 (green)
        ++key;
        for (int i = 0; i < kSamples; ++i) {
          const auto u = [&](std::uint32_t d) { return double(gpu::rngUniform(key, 0, static_cast<std::uint32_t>(i), d)); };
          const dvec3 wi = glm::normalize(sampleDirection(sampling, m, n, wo, u(0), u(1), u(2)));
          const double pdf = directionPdf(sampling, m, n, wi, wo);
          const double x = pdf > 0.0 ? evalBrdf(m, n, wi, wo).y * glm::dot(n, wi) / pdf : 0.0;
          sum += x;
          squares += x * x;
        }
        const double mean = sum / kSamples, error = std::sqrt((squares / kSamples - mean * mean) / kSamples);
        EXPECT_LT(std::abs(mean - albedo.y), 3.89 * error + 1e-4 * albedo.y)
            << "brdf " << int(m.brdf) << " shininess " << m.shininess << " roughness " << m.roughness << " cos(wo) "
            << cosO << " sampling " << int(sampling) << ": " << mean << " +- " << error << ", albedo " << albedo.y;
      }
    }
}

TEST(PathBrdf, ZeroBelowTheSurfaceAndSymmetric) {
  const dvec3 n(0, 0, 1), wo = glm::normalize(dvec3(0.3, 0.1, 0.8)), wi = glm::normalize(dvec3(-0.5, 0.2, 0.6));
  for (const Material& m : {glossy(BrdfModel::Phong, 10), glossy(BrdfModel::Ggx, 0.4)}) {
    EXPECT_EQ(evalBrdf(m, n, dvec3(0.6, 0, -0.8), wo), dvec3(0.0));
    EXPECT_EQ(evalBrdf(m, n, wi, dvec3(0.6, 0, -0.8)), dvec3(0.0));
    EXPECT_EQ(directionPdf(Sampling::Brdf, m, n, dvec3(0.6, 0, -0.8), wo), 0.0);
  }
  // GGX is reciprocal: f(wi, wo) = f(wo, wi).
  const Material ggx = glossy(BrdfModel::Ggx, 0.4);
  const dvec3 f1 = evalBrdf(ggx, n, wi, wo), f2 = evalBrdf(ggx, n, wo, wi);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f1[k], f2[k], 1e-12 * f1[k]);
  // A diffuse material: kd / pi.
  Material lambert;
  lambert.diffuse = dvec3(0.5);
  EXPECT_DOUBLE_EQ(evalBrdf(lambert, n, wi, wo).x, 0.5 / kPi);
}

// The Phong lobe's sampled directions (doc/path-tracing.md, "BRDFs": density cos^s(alpha) (s + 1)
// / 2 pi about the mirror direction r): over a fine grid of the two numbers, the mean of
// cos(alpha) is (s + 1) / (s + 2) and of cos^2(alpha) (s + 1) / (s + 3), and the azimuth about
// r is even (the mean of the component along a vector perpendicular to r is 0).
TEST(PathBrdf, PhongLobeSamplesHaveTheLobesMoments) {
  const dvec3 n = glm::normalize(dvec3(0.1, 1.0, 0.2)), wo = glm::normalize(dvec3(0.4, 0.8, -0.3));
  const dvec3 r = glm::normalize(2.0 * glm::dot(n, wo) * n - wo);
  const dvec3 across = glm::normalize(glm::cross(r, n));
  for (double s : {1.0, 10.0, 200.0}) {
    Material m;
    m.diffuse = dvec3(0.0);
    m.specular = dvec3(0.8);
    m.shininess = s;
    ASSERT_DOUBLE_EQ(specularLobeProbability(m), 1.0);
    // Fine in u, whose map u^(1/(s+1)) is steep near 0 (the midpoint rule's error there
    // shrinks as the step to the power 1 + 1/(s+1)).
    const int stepsU = 8192, stepsV = 32;
    double c1 = 0, c2 = 0, side = 0;
    for (int i = 0; i < stepsU; ++i)
      for (int j = 0; j < stepsV; ++j) {
        const dvec3 wi = sampleDirection(Sampling::Brdf, m, n, wo, (i + 0.5) / stepsU, (j + 0.5) / stepsV, 0.5);
        const double c = glm::dot(wi, r);
        c1 += c;
        c2 += c * c;
        side += glm::dot(wi, across);
      }
    const double count = static_cast<double>(stepsU) * stepsV;
    EXPECT_NEAR(c1 / count, (s + 1) / (s + 2), 1e-5) << "shininess " << s;
    EXPECT_NEAR(c2 / count, (s + 1) / (s + 3), 1e-5) << "shininess " << s;
    EXPECT_NEAR(side / count, 0.0, 1e-9) << "shininess " << s;
  }
}

}  // namespace
}  // namespace vkrt
