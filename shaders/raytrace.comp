// raytrace.comp: the pixels of a band, shared out over the invocations dispatched: each
// workgroup takes a run of adjacent 8x8 tiles (about kDefaultPixelsPerInvocation), and each
// lane the same pixel of each tile in turn, starting its next pixel in the same pass of the
// main loop as it ends one, so that the lanes of a SIMD vector stay busy until their pixels
// run out, and stay near each other. Which lane computes a pixel is fixed (no atomics). Per
// pixel: camera ray, nearest hit through the BVH, shading with shadow rays, and an iterative
// mirror loop carrying a throughput weight, bounded by maxdepth. Written as a state machine
// of bounded steps so that no invocation exceeds llvmpipe's loop budget: an invocation that
// runs out of steps saves its state (its pixel's, and which tile) and the host dispatches
// again (see kDefaultStepBudget in gpu_limits.h).
// Its math is float32 and written independently of the CPU reference (host/cpu/).
#version 450
#extension GL_GOOGLE_include_directive : require

#include "gpu_types.h"

// Specialization constants: only what changes the code: what the scene contains, and the
// exactness cut-off (gpu_whitted.h, kSpec*).
#include "scene_features.glsl"
layout(constant_id = kSpecHasSpecular) const bool kHasSpecular = true;
layout(constant_id = kSpecCutoff) const bool kCutoff = true;

#include "whitted_host.glsl"   // pc, states[], the scene, traversal; the lane's pixel of each tile in turn

// ---- per-invocation state (registers; saved to states[] only on suspension) -----------------
// (the ray, its hit, the shadow ray and the traversal stack: traverse.glsl)
vec3 throughput, radiance;
vec3 lightColor;   // of the current shadow ray: the light's colour over its attenuation
uint depth;

// ---- the state machine's steps -----------------------------------------------------------------

// The nearest hit is known: ambient and emission, then the lights one by one.
void beginShading() {
  surfaceAtHit();
  GpuMaterial m = loadMaterial(hitMaterial);
  radiance += throughput * (m.ambient.rgb + m.emission.rgb);
  lightIndex = 0u;
  phase = kPhaseLight;
}

// The exactness cut-off (GpuCutoff): true when the rest of a path whose next segment
// has weight `weight` and is segment `nextDepth` cannot change any byte of the pixel, as the
// output encodes it (host/image/encode.h: floor(clamp(c, 0, 1) * 255) in float, gamma 1).
bool restCannotChangePixel(vec3 weight, uint nextDepth) {
  bool nonNegative = pc.cutoff.bound.w != 0.0;
  if (nonNegative && all(greaterThanEqual(radiance, vec3(1.0)))) return true;   // saturated
  // 1 + s + ... + s^(n-1) for the n segments left: at most n, and at most 1 / (1 - s) when
  // s < 1 (cheaper than the exact sum, and still an upper bound).
  float n = float(params.maxDepth - nextDepth + 1u);
  vec3 s = pc.cutoff.specular.rgb;
  vec3 series = mix(vec3(n), min(vec3(n), 1.0 / max(1.0 - s, vec3(1e-30))), lessThan(s, vec3(1.0)));
  // A margin for float rounding in the sums the bound stands for.
  vec3 reach = abs(weight) * pc.cutoff.bound.rgb * series * 1.001 + 1e-6;
  if (!all(lessThan(reach, vec3(kInfinity)))) return false;
  vec3 low = nonNegative ? radiance : radiance - reach, high = radiance + reach;
  vec3 lowBytes = floor(clamp(low, 0.0, 1.0) * 255.0), highBytes = floor(clamp(high, 0.0, 1.0) * 255.0);
  return all(equal(lowBytes, highBytes));
}

// After the last light: the mirror ray, or the end of the path.
void reflectOrFinish() {
  vec3 specular = loadMaterial(hitMaterial).specular.rgb;
  if (kHasSpecular && depth < params.maxDepth && any(notEqual(specular, vec3(0.0))) &&
      !(kCutoff && restCannotChangePixel(throughput * specular, depth + 1u))) {
    ++depth;
    ++secondaryRays;
    throughput *= specular;
    vec3 mirror = normalize(rayDir - 2.0 * dot(rayDir, hitNormal) * hitNormal);
    startRay(hitPoint, mirror, secondaryTMin(abs(dot(mirror, hitNormal))));
  } else {
    phase = kPhaseEnd;
  }
}

// Finds the next light that can contribute and starts its shadow ray (kPhaseShadow); lights
// behind the surface are passed over in the same pass, each a step of the budget. After the
// last light: the mirror ray, or the end of the path.
void lightStep(inout uint step) {
  while (phase == kPhaseLight && lightIndex < params.lightCount && step < params.stepBudget) {
    GpuLight light = loadLight(lightIndex);
    float reach;
    vec3 arriving;
    vec3 toLight = towardLight(light, hitPoint, reach, arriving);
    float nDotL = dot(hitNormal, toLight);
    if (!(nDotL > 0.0)) {   // a light behind the surface adds nothing (doc/scene-format.md, "Shading")
      ++lightIndex;
      ++step;
      continue;
    }
    ++shadowRays;
    lightColor = arriving;
    startShadowTraversal(toLight, reach, nDotL);
  }
  if (phase == kPhaseLight && lightIndex >= params.lightCount) reflectOrFinish();
}

void addLightContribution() {
  GpuMaterial m = loadMaterial(hitMaterial);
  vec3 lit = m.diffuse.rgb * shadowCos;
  if (kHasSpecular) {
    vec3 halfVector = normalize(shadowDir - rayDir);
    // At most 1, as it is exactly: float rounding may give 1 + 1e-7, and a high shininess would
    // raise that above the exactness cut-off's bound.
    float nDotH = clamp(dot(hitNormal, halfVector), 0.0, 1.0);
    float shininess = m.specular.w;
    // pow(0, s) is undefined in GLSL: define it as C does (1 for s = 0, else 0).
    float highlight = nDotH > 0.0 ? pow(nDotH, shininess) : (shininess == 0.0 ? 1.0 : 0.0);
    lit += m.specular.rgb * highlight;
  }
  radiance += throughput * lightColor * lit;
}

// The shadow ray's answer: the light's contribution when nothing is in the way.
void onShadowResult(bool blocked) {
  if (!blocked) addLightContribution();
  ++lightIndex;
  phase = kPhaseLight;
}

// ---- suspension ----------------------------------------------------------------------------------

void saveTechniqueState(uint slot) {
  states[slot].throughput = vec4(throughput, 0.0);
  states[slot].radiance = vec4(radiance, 0.0);
  states[slot].lightColor = vec4(lightColor, 0.0);
  states[slot].depth = depth;
}

void loadTechniqueState(uint slot) {
  throughput = states[slot].throughput.rgb;
  radiance = states[slot].radiance.rgb;
  lightColor = states[slot].lightColor.rgb;
  depth = states[slot].depth;
}

// ---- pixels ----------------------------------------------------------------------------------

// A pixel starts: no radiance yet, at full weight, and its camera ray.
void startPixel() {
  radiance = vec3(0.0);
  throughput = vec3(1.0);
  depth = 0u;
  startCameraRay();
}
vec3 pixelColor() { return radiance; }

#include "driver.glsl"   // main(): the step loop, suspension, the done marker, the counters
