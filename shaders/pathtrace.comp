// pathtrace.comp: the path integrators of doc/path-tracing.md (analyticdirect, direct, pathtracer).
// One invocation per pixel of a band renders that pixel's samples [firstSample, firstSample +
// sampleCount) one after another and adds them up in float. Each sample is a path: camera
// ray, then at each vertex emission, light samples (quad lights and emissive triangles and
// spheres, by next-event estimation; point and directional lights always) with shadow rays,
// and a scattered ray, as GpuPathParams says. Random numbers come from the counter-based
// generator of gpu_rng.h, drawn by the rules it points to, so that the CPU reference
// follows the same paths.
// Like raytrace.comp it is a state machine of bounded steps: a pixel that runs out of steps
// saves its state (GpuPathTracerState) and the host dispatches again, so that no invocation
// exceeds llvmpipe's loop budget whatever the path length (see kDefaultStepBudget).
// Its math is float32 and written independently of the CPU reference (host/cpu/).
// Built twice (CMakeLists.txt): whole, and with VKRT_QUAD_LIGHTS_ONLY, without the code of
// point and directional lights, emissive surfaces as lights and analyticdirect's closed form,
// for the variants, specialised and general, of scenes that use none of them (most of the
// course's): code
// that specialization constants make dead still costs lavapipe its translation and inlining
// when the pipeline is created (bench/README.md, "Path tracing on lavapipe").
#version 450
#extension GL_GOOGLE_include_directive : require

#include "gpu_types.h"

// Specialization constants: what the scene contains, and the integrator settings (gpu_path.h,
// kPathSpec*).
#include "scene_features.glsl"
layout(constant_id = kPathSpecHasQuadLights) const bool kHasQuadLights = true;
layout(constant_id = kPathSpecHasGgx) const bool kHasGgx = true;
layout(constant_id = kPathSpecIntegrator) const uint kSpecIntegrator = kPathSpecFromParams;
layout(constant_id = kPathSpecNextEvent) const uint kSpecNextEvent = kPathSpecFromParams;
layout(constant_id = kPathSpecSampling) const uint kSpecSampling = kPathSpecFromParams;
layout(constant_id = kPathSpecRussianRoulette) const uint kSpecRussianRoulette = kPathSpecFromParams;
layout(constant_id = kPathSpecStratified) const uint kSpecStratified = kPathSpecFromParams;
layout(constant_id = kPathSpecJitter) const uint kSpecJitter = kPathSpecFromParams;
layout(constant_id = kPathSpecHasEmitters) const bool kHasEmitters = true;
layout(constant_id = kPathSpecSampler) const uint kSpecSampler = kPathSpecFromParams;

layout(push_constant) uniform Push { GpuPathPush pc; };

#define TechniqueState GpuPathTracerState
#include "technique.glsl"   // pixels[] (rgb the sum of the pixel's finished samples), states[], the scene, traversal, tiles
#include "mis_weight.glsl"

// The path's settings and camera, the way params.glsl takes the render's: a storage buffer,
// copied into the private `path` by main's first lines.
layout(std430, binding = kBindingPathParams) readonly buffer PathParams { GpuPathParams pathStored; };
GpuPathParams path;
void copyTechniqueParams() { path = pathStored; }

#ifdef VKRT_TEXEL_READS
SCENE_TEXELS(kBindingQuadLights) quadLightWords;   // kQuadLightTexels each
GpuQuadLight loadQuadLight(uint i) {
  const uint n = kQuadLightTexels;
  GpuQuadLight q;
  q.corner = texelF(quadLightWords, n * i);
  q.edgeAB = texelF(quadLightWords, n * i + 1u);
  q.edgeAC = texelF(quadLightWords, n * i + 2u);
  q.normal = texelF(quadLightWords, n * i + 3u);
  q.radiance = texelF(quadLightWords, n * i + 4u);
  return q;
}
#else
layout(std430, binding = kBindingQuadLights) readonly buffer QuadLights { GpuQuadLight quadLights[]; };
GpuQuadLight loadQuadLight(uint i) { return quadLights[i]; }
#endif

// The emissive triangles and spheres that next-event estimation samples (path.emitterCount).
layout(std430, binding = kBindingEmitters) readonly buffer Emitters { GpuEmitter emitters[]; };

// The integrator settings: specialised, or read from GpuPathParams (kPathSpecFromParams).
uint integrator() { return kSpecIntegrator != kPathSpecFromParams ? kSpecIntegrator : path.integrator; }
uint nextEvent() { return kSpecNextEvent != kPathSpecFromParams ? kSpecNextEvent : path.nextEvent; }
uint sampling() { return kSpecSampling != kPathSpecFromParams ? kSpecSampling : path.sampling; }
bool russianRoulette() {
  return kSpecRussianRoulette != kPathSpecFromParams ? kSpecRussianRoulette != 0u : path.russianRoulette != 0u;
}
bool stratified() { return kSpecStratified != kPathSpecFromParams ? kSpecStratified != 0u : path.lightStrata > 0u; }
bool jitter() { return kSpecJitter != kPathSpecFromParams ? kSpecJitter != 0u : path.jitter != 0u; }
bool stratifiedSamples() { return kSpecSampler != kPathSpecFromParams ? kSpecSampler != 0u : path.strataSide != 0u; }

// ---- per-pixel state (registers; saved to states[] only on suspension) ----------------------
// (the ray, its hit, the shadow ray and the traversal stack: traverse.glsl)
vec3 throughput;       // T: the path's weight up to the current vertex
vec3 radiance;         // this sample's radiance so far
vec3 pixelSum;         // the pixel's finished samples, added in sample order
float lastPdf;         // solid-angle pdf of the scatter that made the current ray (MIS)
vec3 pending;          // what the current shadow ray adds when nothing blocks it
uint bounce, sampleIndex;
uint pixelX, pixelY, pixelIndex;   // in the full image; pixelIndex = y * fullWidth + x
uint pixelSlot;        // the pixel's place in the band's pixels[]

// ---- random numbers (gpu_rng.h: the generator and how each number is used) ------------------

uint sampleKey;   // rngSampleKey of the current sample
uint pixelKey;    // rngPixelKey of the current pixel (stratified samples)
void keySample() {
  sampleKey = rngSampleKey(path.seed, pixelIndex, path.firstSample + sampleIndex);
  pixelKey = rngPixelKey(path.seed, pixelIndex);
}

// The stratum of `pair` in the current sample, or kRngNotStratified (independent numbers).
uint pairStratum(uint pair) {
  if (!stratifiedSamples()) return kRngNotStratified;
  return rngPairStratum(pixelKey, path.firstSample + sampleIndex, pair, path.strataSide);
}

// The number of `dimension`, in `stratum` of its pair.
float randomIn(uint dimension, uint stratum) {
  float r = rngUniformKeyed(sampleKey, dimension);
  if (stratum == kRngNotStratified) return r;
  return rngInCell(r, rngStratumCell(stratum, dimension, path.strataSide), path.strataSide);
}

// The strata of the current vertex's stratified pairs, its direction's and its first light
// sample's, set by stratifyVertex where a vertex begins and on resuming. lavapipe inlines
// every call and runs each copy whenever it is reached, taken or not: the permutation is
// computed at these two places and the camera's, not at each of the numbers drawn.
uint directionStratum = kRngNotStratified, lightStratum = kRngNotStratified;
void stratifyVertex() {
  directionStratum = pairStratum(rngDirectionPair(bounce));
  lightStratum = pairStratum(rngLightPair(bounce));
}

// The number of `slot` at the current path vertex.
float randomAt(uint slot) {
  uint dimension = rngDimension(bounce, slot);
  uint pair = rngStratifiedPair(dimension);
  return randomIn(dimension, pair == rngDirectionPair(bounce) ? directionStratum
                             : pair == rngLightPair(bounce)   ? lightStratum
                                                              : kRngNotStratified);
}

#include "brdf.glsl"   // (after sampling() and randomAt(), which it uses)

// ---- analyticdirect: the closed form (doc/path-tracing.md, "Integrators") ------------------------

// Phi(x) = 1/2 sum_k theta_k Gamma_k over the corners a, a+ab, a+ab+ac, a+ac; 0 behind the
// light (it emits on one side).
vec3 polygonIrradianceVector(GpuQuadLight q, vec3 x) {
  if (!(dot(q.normal.xyz, x - q.corner.xyz) > 0.0)) return vec3(0.0);
  vec3 v[4] = vec3[4](q.corner.xyz - x, q.corner.xyz + q.edgeAB.xyz - x,
                      q.corner.xyz + q.edgeAB.xyz + q.edgeAC.xyz - x, q.corner.xyz + q.edgeAC.xyz - x);
  vec3 phi = vec3(0.0);
  for (uint k = 0u; k < 4u; ++k) {
    vec3 p = v[k], r = v[(k + 1u) & 3u];
    vec3 across = cross(p, r);
    // The angle between p and r; atan2 keeps its precision where acos of a dot product does not.
    float theta = atan(length(across), dot(p, r));
    phi += theta * normalize(across);
  }
  return 0.5 * phi;
}

// ---- emissive triangles and spheres as lights (gpu_scene.h, GpuEmitter) -----------------------

// Whether next-event estimation samples the emitters (beyond the course: the path tracer's
// `nexteventestimation on` and `mis`).
bool samplesEmitters() {
  return kHasEmitters && integrator() == kIntegratorPathTracer && nextEvent() != kNextEventOff &&
         path.emitterCount > 0u;
}

// The density per world area with which a light sample draws a point of a triangle of
// material m (pick x area pdf): sum(|emission|) / total weight; an ellipsoid's is this times
// sphereDensityFactor.
float emitterAreaDensity(GpuMaterial m) {
  return (abs(m.emission.r) + abs(m.emission.g) + abs(m.emission.b)) * path.emitterWeightScale;
}

// The solid-angle density with which a light sample finds the current hit (an emissive
// triangle or sphere of material m, at distance bestT along rayDir) from the vertex before.
float emitterHitPdf(GpuMaterial m) {
  vec3 normal;
  float factor = densityFactorAt(hitPrim, hitPoint, normal);
  return emitterAreaDensity(m) * factor * bestT * bestT / abs(dot(normal, rayDir));
}

// ---- the state machine's steps -----------------------------------------------------------------

// The camera ray of sample `sampleIndex` (gpu_rng.h: the pixel centre, or jittered).
void startCamera() {
  keySample();
  float u = 0.5, v = 0.5;
  if (jitter()) {
    uint stratum = pairStratum(kRngCameraPair);
    u = randomIn(kRngPixelX, stratum);
    v = randomIn(kRngPixelY, stratum);
  }
  vec3 dir = cameraRayDirection(path.camera, uvec2(pixelX, pixelY), vec2(u, v));
  throughput = vec3(1.0);
  radiance = vec3(0.0);
  bounce = 0u;
  lastPdf = 0.0;
  startRay(path.camera.origin.xyz, dir, 0.0);
}

// The sample is over. The steps that end it only say so, and the main loop calls endPath
// once per iteration: lavapipe would run an inlined copy at each call site.
void finishSample() { phase = kPhaseEnd; }

// The lane's pixel in `tile` (its place in the tile is the lane's): whether it lies inside
// the band (the last tiles of a row or of the band may stick out). Sets the pixel's
// coordinates in the full image (a crop draws the full render's random numbers and camera
// rays) and its pixelSlot.
bool setPixel() {
  uint x = (tile % params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.x;
  uint yInBand = (tile / params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.y;
  if (x >= params.width || yInBand >= bandRows) return false;
  pixelSlot = yInBand * params.width + x;
  pixelX = x + params.originX;
  pixelY = pc.bandY0 + yInBand + params.originY;
  pixelIndex = pixelY * params.fullWidth + pixelX;
  return true;
}
uint bandSlot() { return pixelSlot; }

// Adds the sample to the pixel (a NaN or infinite one is counted and left out), then starts
// the next; after the pixel's last, writes the pixel and starts the same place in the next
// tile of the lane's run, if any: a lane renders the samples of several pixels in turn, so
// that its vector's lanes, whose paths end at different lengths, stay busy. (One call of
// startCamera: lavapipe would inline a copy at each.) A pixel of no samples comes here
// before any and is written at once.
void endPath() {
  if (sampleIndex < path.sampleCount) {
    if (any(isnan(radiance)) || any(isinf(radiance)))
      ++nonFinite;
    else
      pixelSum += radiance;
    ++sampleIndex;
    ++finished;
  }
  if (sampleIndex >= path.sampleCount) {
    pixels[pixelSlot] = vec4(pixelSum, 1.0);
    bool found = false;
    while (!found && ++tile < runEnd) found = setPixel();
    if (!found) {
      phase = kPhaseDone;
      return;
    }
    pixelSum = vec3(0.0);
    sampleIndex = 0u;
    if (path.sampleCount == 0u) return;   // (the next step writes it)
  }
  startCamera();
}

// Quad-light samples at a vertex: one per light for analyticdirect, N per light otherwise.
uint quadLightSamples() {
  return path.quadLightCount * (integrator() == kIntegratorAnalyticDirect ? 1u : path.lightSamples);
}

// The nearest hit is known: its emission, then the lights (kPhaseLight), or the end of the path.
void beginShading() {
  stratifyVertex();
  hitPoint = rayOrigin + bestT * rayDir;
  surfaceAt(hitPrim, rayOrigin, rayDir, bestT, vec2(bestB1, bestB2), hitPoint, path.camera.origin.xyz, hitNormal,
            hitMaterial);
  GpuMaterial m = loadMaterial(hitMaterial);
  if (kHasQuadLights && m.emission.w != kNoQuadLight) {
    // A quad light: radiance L on its front side, black behind; it reflects nothing.
    GpuQuadLight q = loadQuadLight(uint(m.emission.w));
    float cosLight = -dot(q.normal.xyz, rayDir);
    if (cosLight > 0.0) {
      float weight = 1.0;   // camera rays, and every ray without next-event estimation
      if (bounce > 0u && nextEvent() == kNextEventOn) {
        weight = 0.0;   // the light samples of the vertex before counted it
      } else if (bounce > 0u && nextEvent() == kNextEventMis) {
        // Power heuristic against the light samples: pdfs in solid angle at the vertex before.
        weight = powerHeuristic(lastPdf, bestT * bestT / (q.corner.w * cosLight));
      }
      radiance += throughput * weight * q.radiance.rgb;
    }
    finishSample();
    return;
  }
  // Other emission: found by hitting only, unless the light samples of the vertex before
  // counted it (NEE on) or weighted it against this ray (MIS).
  vec3 emitted = m.emission.rgb;
#ifndef VKRT_QUAD_LIGHTS_ONLY
  if (kHasEmitters && bounce > 0u && samplesEmitters() && any(notEqual(emitted, vec3(0.0)))) {
    if (nextEvent() == kNextEventOn) {
      emitted = vec3(0.0);
    } else {
      emitted *= powerHeuristic(lastPdf, emitterHitPdf(m));
    }
  }
#endif
  radiance += throughput * emitted;
  bool analytic = integrator() == kIntegratorAnalyticDirect;
  // Whether this vertex samples lights and scatters: the depth rule of doc/path-tracing.md, "Depth"
  // (vertex `bounce` may when bounce < maxdepth, kMaxBounces with no limit), one vertex for
  // direct lighting.
  bool scatters = integrator() == kIntegratorPathTracer
                      ? bounce < min(path.maxDepth, kMaxBounces)
                      : bounce == 0u;
  // f = 0 unless w_o is on the side of the normal (the closed form does not look at w_o).
  if (!scatters || (!analytic && !(dot(hitNormal, rayDir) < 0.0))) {
    finishSample();
    return;
  }
  bool quadSamples = integrator() != kIntegratorPathTracer || nextEvent() != kNextEventOff;
  lightIndex = quadSamples ? 0u : quadLightSamples();
  phase = kPhaseLight;
}

// Starts the shadow ray of a light sample that adds `contribution` when nothing blocks it.
void startShadowRay(vec3 dir, float tMax, float cosine, vec3 contribution) {
  ++shadowRays;
  pending = contribution;
  startShadowTraversal(dir, tMax, cosine);
}

// The (s, t) of light sample k of a light, from the numbers of `slot` and the one after it:
// with lightstratify, in cell k of an m x m grid (gpu_rng.h, the sampling rules).
vec2 lightSamplePoint(uint k, uint slot) {
  vec2 st = vec2(randomAt(slot), randomAt(slot + 1u));
  if (stratified()) {
    float cells = float(path.lightStrata);
    st = (vec2(float(k % path.lightStrata), float(k / path.lightStrata)) + st) / cells;
  }
  return st;
}

// Sample k of quad light j by next-event estimation.
void quadLightSample(uint j, uint k, GpuMaterial m) {
  GpuQuadLight q = loadQuadLight(j);
  vec2 st = lightSamplePoint(k, kRngSlotLightBase + 2u * (j * path.lightSamples + k));
  vec3 onLight = q.corner.xyz + st.x * q.edgeAB.xyz + st.y * q.edgeAC.xyz;
  vec3 d = onLight - hitPoint;
  float distance2 = dot(d, d);
  float distance = sqrt(distance2);
  vec3 wi = d / distance;
  float cosSurface = dot(hitNormal, wi), cosLight = -dot(q.normal.xyz, wi);
  if (!(cosSurface > 0.0 && cosLight > 0.0)) return;
  vec3 f = brdf(m, hitNormal, wi, -rayDir);
  // (A / N) L f G, G = cos cos' / |x - x'|^2.
  vec3 c = throughput * f * q.radiance.rgb *
           (cosSurface * cosLight / distance2 * q.corner.w / float(path.lightSamples));
  if (integrator() == kIntegratorPathTracer && nextEvent() == kNextEventMis) {
    c *= powerHeuristic(distance2 / (q.corner.w * cosLight), scatterPdf(m, hitNormal, wi, -rayDir));
  }
  if (any(notEqual(c, vec3(0.0)))) startShadowRay(wi, distance * kQuadShadowSpan, cosSurface, c);
}

// Point or directional light i: always sampled (it cannot be hit). analyticdirect takes it
// like its quad lights: diffuse only, no shadow.
void pointLightSample(uint i, GpuMaterial m, bool analytic) {
  GpuLight light = loadLight(i);
  float tMax;
  vec3 arriving;
  vec3 wi = towardLight(light, hitPoint, tMax, arriving);
  float cosSurface = dot(hitNormal, wi);
  if (!(cosSurface > 0.0)) return;
  vec3 f = analytic ? m.diffuse.rgb * kInvPi : brdf(m, hitNormal, wi, -rayDir);
  vec3 c = throughput * f * arriving * cosSurface;
  if (analytic)
    radiance += c;
  else if (any(notEqual(c, vec3(0.0))))
    startShadowRay(wi, tMax, cosSurface, c);
}

// Light sample k of N of the emissive triangles and spheres (the sampling rules of gpu_rng.h): an
// emitter picked from the cumulative table, a point on it, and its shadow ray, which stops
// short of the point by the emitter's secondary-ray offset there. Each iteration of the
// table's binary search is a step of the budget.
void emitterSample(uint k, GpuMaterial m, inout uint step) {
  uint n = path.lightSamples;
  vec2 st = lightSamplePoint(k, rngEmitterPointSlot(path.quadLightCount, n, k));
  float u = randomAt(rngEmitterPickSlot(path.quadLightCount, n, k));
  uint lo = 0u, hi = path.emitterCount;   // the first entry whose cdf exceeds u
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (emitters[mid].cdf > u)
      hi = mid;
    else
      lo = mid + 1u;
    ++step;
  }
  uint prim = emitters[min(lo, path.emitterCount - 1u)].primRef;
  vec3 x, normal;
  float factor, primitiveOffset;
  uint material;
  samplePoint(prim, st.x, st.y, x, normal, factor, material, primitiveOffset);
  GpuMaterial light = loadMaterial(material);
  vec3 d = x - hitPoint;
  float distance2 = dot(d, d);
  float distance = sqrt(distance2);
  vec3 wi = d / distance;
  float cosSurface = dot(hitNormal, wi), cosLight = abs(dot(normal, wi));
  if (!(distance > 0.0 && cosSurface > 0.0 && cosLight > 0.0)) return;
  float lightPdf = emitterAreaDensity(light) * factor * distance2 / cosLight;
  vec3 c = throughput * brdf(m, hitNormal, wi, -rayDir) * light.emission.rgb * (cosSurface / (lightPdf * float(n)));
  if (nextEvent() == kNextEventMis) {
    c *= powerHeuristic(lightPdf, scatterPdf(m, hitNormal, wi, -rayDir));
  }
  if (any(notEqual(c, vec3(0.0))))
    startShadowRay(wi, distance - secondaryTMinAt(primitiveOffset, x, path.camera.origin.xyz, cosLight), cosSurface, c);
}

// Leaves the vertex along a sampled direction, or ends the path.
void scatter(GpuMaterial m) {
  vec3 wo = -rayDir;
  vec3 wi = normalize(sampleDirection(m, hitNormal, wo));
  float cosine = dot(hitNormal, wi);
  float pdf = scatterPdf(m, hitNormal, wi, wo);
  if (!(cosine > 0.0 && pdf > 0.0)) {
    finishSample();
    return;
  }
  throughput *= brdf(m, hitNormal, wi, wo) * (cosine / pdf);
  // Possibly terminate the path with Russian roulette (on the throughput).
  if (russianRoulette()) {
    float p = min(max(throughput.r, max(throughput.g, throughput.b)), 1.0);
    if (!(randomAt(kRngSlotRoulette) < p)) {
      finishSample();
      return;
    }
    throughput /= p;
  }
  if (all(equal(throughput, vec3(0.0)))) {   // nothing more can be added
    finishSample();
    return;
  }
  lastPdf = pdf;
  ++bounce;
  ++secondaryRays;
  startRay(hitPoint, wi, secondaryTMin(cosine));
}

// One light sample of the vertex (each is a step), then the scatter.
void lightStep(inout uint step) {
  GpuMaterial m = loadMaterial(hitMaterial);
  uint quad = quadLightSamples();
  if (kHasQuadLights && lightIndex < quad) {
    uint i = lightIndex++;
#ifndef VKRT_QUAD_LIGHTS_ONLY
    if (integrator() == kIntegratorAnalyticDirect) {
      GpuQuadLight q = loadQuadLight(i);
      radiance += throughput * m.diffuse.rgb * kInvPi * q.radiance.rgb * dot(polygonIrradianceVector(q, hitPoint), hitNormal);
      return;
    }
#endif
    quadLightSample(i / path.lightSamples, i % path.lightSamples, m);
    return;
  }
#ifndef VKRT_QUAD_LIGHTS_ONLY
  if ((kHasPointLights || kHasDirectionalLights) && lightIndex < quad + path.lightCount) {
    pointLightSample(lightIndex++ - quad, m, integrator() == kIntegratorAnalyticDirect);
    return;
  }
  if (kHasEmitters && samplesEmitters() && lightIndex < quad + path.lightCount + path.lightSamples) {
    emitterSample(lightIndex++ - quad - path.lightCount, m, step);
    return;
  }
#endif
  if (integrator() == kIntegratorPathTracer)
    scatter(m);
  else
    finishSample();
}

// The shadow ray's answer: the light sample's contribution when nothing is in the way.
void onShadowResult(bool blocked) {
  if (!blocked) radiance += pending;
  phase = kPhaseLight;
}

// ---- suspension ----------------------------------------------------------------------------------

void saveTechniqueState(uint slot) {
  states[slot].throughput = vec4(throughput, 0.0);
  states[slot].radiance = vec4(radiance, 0.0);
  states[slot].pixelSum = vec4(pixelSum, lastPdf);
  states[slot].pending = vec4(pending, 0.0);
  states[slot].bounce = bounce;
  states[slot].sampleIndex = sampleIndex;
}

void loadTechniqueState(uint slot) {
  throughput = states[slot].throughput.rgb;
  radiance = states[slot].radiance.rgb;
  pixelSum = states[slot].pixelSum.rgb;
  lastPdf = states[slot].pixelSum.w;
  pending = states[slot].pending.rgb;
  bounce = states[slot].bounce;
  sampleIndex = states[slot].sampleIndex;
}

// ---- the lane's pixels ------------------------------------------------------------------------

// The lane's first pixel of its run: its first sample's camera ray (a pixel of no samples
// goes to endPath at once, which writes it).
void startFirstPixel() {
  pixelSum = vec3(0.0);
  sampleIndex = 0u;
  if (path.sampleCount > 0u)
    startCamera();
  else
    phase = kPhaseEnd;
}

// A suspended lane goes on (its state loaded, its pixel set): the sample's keys and the
// vertex's strata, which are not saved.
void resumePixel() {
  keySample();
  stratifyVertex();
}

#include "driver.glsl"   // main(): the step loop, suspension, the done marker, the counters
