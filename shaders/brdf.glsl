// brdf.glsl: the path integrators' BRDFs (doc/path-tracing.md, "BRDFs"): Phong and GGX, their
// values, the pdf of the scatter step and its sampling by the rules of gpu_rng.h. Include
// in pathtrace.comp after intersect.glsl (kPi), the specialization constant kHasGgx and the functions sampling()
// (the scatter rule) and randomAt() (the numbers of the current path vertex).
// Material w fields: ambient.w = model, diffuse.w = GGX alpha, specular.w = Phong exponent.

const float kInvPi = 0.318309886183791;

// pow(x, s) for x >= 0 as C defines it: pow(0, 0) = 1 (GLSL leaves pow(0, s) undefined).
float powSafe(float x, float s) { return x > 0.0 ? pow(x, s) : (s == 0.0 ? 1.0 : 0.0); }
float average(vec3 c) { return (c.r + c.g + c.b) / 3.0; }

// The direction at polar angle theta (sine, cosine) and azimuth phi around the unit axis n,
// in the frame of the sampling rules (gpu_rng.h).
vec3 aroundAxis(vec3 n, float sinTheta, float cosTheta, float phi) {
  vec3 a = abs(n.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(a, n));
  vec3 b = cross(n, t);
  return sinTheta * cos(phi) * t + sinTheta * sin(phi) * b + cosTheta * n;
}

bool isGgx(GpuMaterial m) { return kHasGgx && m.ambient.w == kBrdfGgx; }

// GGX's D, with cos^4 (a^2 + tan^2) written as (a^2 cos^2 + sin^2)^2 (no division by cos).
// Roughness 0 makes D a delta that no sampled or light direction hits: 0 (not 0 / 0).
float ggxD(float alpha, float nDotH) {
  float a2 = alpha * alpha, c2 = nDotH * nDotH;
  if (!(nDotH > 0.0) || a2 == 0.0) return 0.0;
  float d = a2 * c2 + (1.0 - c2);
  return a2 / (kPi * d * d);
}

// Smith's G1 for a direction at cos = n.v > 0.
float ggxG1(float alpha, float nDotV) {
  float c2 = nDotV * nDotV;
  float tan2 = (1.0 - c2) / c2;
  return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * tan2));
}

// f(w_i, w_o), w_o toward the viewer, w_i toward the light; 0 unless both lie on the side of n.
vec3 brdf(GpuMaterial m, vec3 n, vec3 wi, vec3 wo) {
  float nDotI = dot(n, wi), nDotO = dot(n, wo);
  if (!(nDotI > 0.0 && nDotO > 0.0)) return vec3(0.0);
  vec3 f = m.diffuse.rgb * kInvPi;
  if (isGgx(m)) {
    float alpha = m.diffuse.w;
    vec3 h = normalize(wi + wo);
    float d = ggxD(alpha, dot(n, h));
    float g = ggxG1(alpha, nDotI) * ggxG1(alpha, nDotO);
    vec3 fresnel = m.specular.rgb + (1.0 - m.specular.rgb) * pow(1.0 - clamp(dot(wi, h), 0.0, 1.0), 5.0);
    f += fresnel * (g * d / (4.0 * nDotI * nDotO));
  } else {
    float s = m.specular.w;
    vec3 r = 2.0 * nDotO * n - wo;
    f += m.specular.rgb * ((s + 2.0) / (2.0 * kPi) * powSafe(clamp(dot(r, wi), 0.0, 1.0), s));   // (rounding: never above 1)
  }
  return f;
}

// The probability of the specular lobe under `importancesampling brdf` (doc/path-tracing.md, "Estimators"):
// 0 for a lobe with nothing to sample, GGX whose alpha^2 is 0 (D has no density: only the
// diffuse part reflects) and Phong of shininess 0 (flat over the hemisphere: cosine sampling
// takes it all).
float specularLobeChance(GpuMaterial m) {
  if (isGgx(m) ? m.diffuse.w * m.diffuse.w == 0.0 : m.specular.w == 0.0) return 0.0;
  float kd = average(m.diffuse.rgb), ks = average(m.specular.rgb);
  float t = kd + ks > 0.0 ? ks / (kd + ks) : 0.0;
  return isGgx(m) ? max(0.25, t) : t;
}

// The solid-angle pdf with which the scatter step picks w_i.
float scatterPdf(GpuMaterial m, vec3 n, vec3 wi, vec3 wo) {
  float nDotI = dot(n, wi);
  if (!(nDotI > 0.0)) return 0.0;
  if (sampling() == kSamplingHemisphere) return 0.5 * kInvPi;
  if (sampling() == kSamplingCosine) return nDotI * kInvPi;
  float t = specularLobeChance(m);
  float specular;
  if (isGgx(m)) {
    vec3 h = normalize(wi + wo);
    float hDotI = dot(h, wi);
    specular = hDotI > 0.0 ? ggxD(m.diffuse.w, dot(n, h)) * dot(n, h) / (4.0 * hDotI) : 0.0;
  } else {
    float s = m.specular.w;
    vec3 r = 2.0 * dot(n, wo) * n - wo;
    specular = (s + 1.0) / (2.0 * kPi) * powSafe(clamp(dot(r, wi), 0.0, 1.0), s);
  }
  return (1.0 - t) * nDotI * kInvPi + t * specular;
}

// Draws w_i at the current vertex (the sampling rules of gpu_rng.h).
vec3 sampleDirection(GpuMaterial m, vec3 n, vec3 wo) {
  float u = randomAt(kRngSlotDirectionU), v = randomAt(kRngSlotDirectionV);
  float phi = 2.0 * kPi * v;
  if (sampling() == kSamplingHemisphere) return aroundAxis(n, sqrt(max(1.0 - u * u, 0.0)), u, phi);
  if (sampling() == kSamplingBrdf && randomAt(kRngSlotLobe) < specularLobeChance(m)) {
    if (isGgx(m)) {
      float alpha = m.diffuse.w;
      float tanTheta = alpha * sqrt(u) / sqrt(1.0 - u);
      float cosTheta = 1.0 / sqrt(1.0 + tanTheta * tanTheta);
      vec3 h = aroundAxis(n, tanTheta * cosTheta, cosTheta, phi);
      return 2.0 * dot(wo, h) * h - wo;
    }
    float z = pow(u, 1.0 / (m.specular.w + 1.0));
    vec3 r = 2.0 * dot(n, wo) * n - wo;
    return aroundAxis(r, sqrt(max(1.0 - z * z, 0.0)), z, phi);
  }
  return aroundAxis(n, sqrt(u), sqrt(1.0 - u), phi);   // cosine
}
