// BRDF evaluation and sampling for the CPU path integrators, written from doc/path-tracing.md
// (no code shared with the shader).
#include "cpu/path_brdf.h"

#include <algorithm>
#include <cmath>

namespace vkrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

double average(const dvec3& c) { return (c.x + c.y + c.z) / 3.0; }

// The mirror direction of w_o about n: r = 2 (n.w_o) n - w_o.
dvec3 reflectAbout(const dvec3& n, const dvec3& wo) { return 2.0 * glm::dot(n, wo) * n - wo; }

// tan^2 of the angle between unit v and unit n, from its cosine.
double tan2FromCos(double cosine) {
  double c2 = cosine * cosine;
  return std::max(0.0, 1.0 - c2) / c2;
}

// Smith's G1 for GGX (doc/path-tracing.md, "BRDFs").
double ggxG1(double alpha, double cosine) {
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2FromCos(cosine)));
}

// Local (sin theta cos phi, sin theta sin phi, cos theta) around axis n.
dvec3 aroundAxis(const dvec3& n, double cosTheta, double phi) {
  dvec3 t, b;
  frameAround(n, t, b);
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * n;
}

// Cosine-weighted around n: z = sqrt(1 - u), sin = sqrt(u), phi = 2 pi v.
dvec3 cosineDirection(const dvec3& n, double u, double v) {
  dvec3 t, b;
  frameAround(n, t, b);
  double sinTheta = std::sqrt(u), phi = 2.0 * kPi * v;
  return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + std::sqrt(1.0 - u) * n;
}

}  // namespace

void frameAround(const dvec3& n, dvec3& t, dvec3& b) {
  dvec3 a = std::abs(n.x) > 0.9 ? dvec3(0.0, 1.0, 0.0) : dvec3(1.0, 0.0, 0.0);
  t = glm::normalize(glm::cross(a, n));
  b = glm::cross(n, t);
}

double ggxD(double alpha, double nDotH) {
  if (alpha <= 0.0 || nDotH <= 0.0) return 0.0;   // alpha 0 is a delta: no density to give
  double a2 = alpha * alpha, c2 = nDotH * nDotH;
  double s = a2 + tan2FromCos(nDotH);
  return a2 / (kPi * c2 * c2 * s * s);
}

dvec3 evalBrdf(const Material& m, const dvec3& n, const dvec3& wi, const dvec3& wo) {
  const double nDotI = glm::dot(n, wi), nDotO = glm::dot(n, wo);
  if (!(nDotI > 0.0 && nDotO > 0.0)) return dvec3(0.0);
  dvec3 f = m.diffuse / kPi;
  if (m.brdf == BrdfModel::Phong) {
    double rDotI = std::clamp(glm::dot(reflectAbout(n, wo), wi), 0.0, 1.0);   // (rounding: never above 1)
    f += m.specular * ((m.shininess + 2.0) / (2.0 * kPi) * std::pow(rDotI, m.shininess));
  } else {
    dvec3 h = glm::normalize(wi + wo);
    double d = ggxD(m.roughness, glm::dot(n, h));
    double g = ggxG1(m.roughness, nDotI) * ggxG1(m.roughness, nDotO);
    dvec3 fresnel = m.specular + (dvec3(1.0) - m.specular) * std::pow(1.0 - glm::dot(wi, h), 5.0);
    f += fresnel * (g * d / (4.0 * nDotI * nDotO));
  }
  return f;
}

double specularLobeProbability(const Material& m) {
  // A lobe with nothing to sample: GGX whose alpha^2 is 0 in float32, as the shader computes
  // it (D has no density there: only the diffuse part reflects), or Phong of shininess 0 (flat
  // over the hemisphere: cosine sampling takes it all).
  const float alpha = static_cast<float>(m.roughness);
  if (m.brdf == BrdfModel::Phong ? m.shininess == 0.0 : alpha * alpha == 0.0f) return 0.0;
  const double kd = average(m.diffuse), ks = average(m.specular);
  const double ratio = kd + ks > 0.0 ? ks / (kd + ks) : 0.0;
  return m.brdf == BrdfModel::Phong ? ratio : std::max(0.25, ratio);
}

double directionPdf(Sampling sampling, const Material& m, const dvec3& n, const dvec3& wi, const dvec3& wo) {
  const double nDotI = glm::dot(n, wi);
  if (!(nDotI > 0.0)) return 0.0;
  switch (sampling) {
    case Sampling::Hemisphere: return 1.0 / (2.0 * kPi);
    case Sampling::Cosine: return nDotI / kPi;
    case Sampling::Brdf: break;
  }
  const double t = specularLobeProbability(m);
  double specular;
  if (m.brdf == BrdfModel::Phong) {
    double rDotI = std::clamp(glm::dot(reflectAbout(n, wo), wi), 0.0, 1.0);   // (rounding: never above 1)
    specular = (m.shininess + 1.0) / (2.0 * kPi) * std::pow(rDotI, m.shininess);
  } else {
    dvec3 h = glm::normalize(wi + wo);
    double hDotI = glm::dot(h, wi);
    specular = hDotI > 0.0 ? ggxD(m.roughness, glm::dot(n, h)) * glm::dot(n, h) / (4.0 * hDotI) : 0.0;
  }
  return (1.0 - t) * nDotI / kPi + t * specular;
}

double powerHeuristic(double pdfThis, double pdfOther) {
  const double a2 = pdfThis * pdfThis, b2 = pdfOther * pdfOther;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}

dvec3 sampleDirection(Sampling sampling, const Material& m, const dvec3& n, const dvec3& wo, double u, double v,
                      double lobe) {
  const double phi = 2.0 * kPi * v;
  switch (sampling) {
    case Sampling::Hemisphere: return aroundAxis(n, u, phi);
    case Sampling::Cosine: return cosineDirection(n, u, v);
    case Sampling::Brdf: break;
  }
  if (!(lobe < specularLobeProbability(m))) return cosineDirection(n, u, v);
  if (m.brdf == BrdfModel::Phong) return aroundAxis(reflectAbout(n, wo), std::pow(u, 1.0 / (m.shininess + 1.0)), phi);
  // GGX: the half vector around n, then w_o reflected about it.
  double thetaH = std::atan(m.roughness * std::sqrt(u) / std::sqrt(1.0 - u));
  dvec3 h = aroundAxis(n, std::cos(thetaH), phi);
  return 2.0 * glm::dot(wo, h) * h - wo;
}

}  // namespace vkrt
