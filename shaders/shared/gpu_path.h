// gpu_path.h: pathtrace.comp's own interface (the path integrators, doc/path-tracing.md):
// the integrators' ids, its bindings and specialization ids, its parameters, push constants
// and suspended state.
#ifndef VKRT_GPU_PATH_H
#define VKRT_GPU_PATH_H

#include "gpu_render.h"
#include "gpu_rng.h"

GPU_BEGIN

// Path integrators (doc/path-tracing.md, "Integrators"); the ids the shader and the host share.
GPU_CONST uint kIntegratorRaytracer = 0u;
GPU_CONST uint kIntegratorAnalyticDirect = 1u;
GPU_CONST uint kIntegratorDirect = 2u;
GPU_CONST uint kIntegratorPathTracer = 3u;
GPU_CONST uint kNextEventOff = 0u;
GPU_CONST uint kNextEventOn = 1u;
GPU_CONST uint kNextEventMis = 2u;
GPU_CONST uint kSamplingHemisphere = 0u;
GPU_CONST uint kSamplingCosine = 1u;
GPU_CONST uint kSamplingBrdf = 2u;

// It reads the scene at the bindings of raytrace.comp (the shapes' .. kBindingPrimRefs),
// and shares kBindingPathStates, kBindingCounters and kBindingParams (GpuRenderParams: sizes,
// bands, tiles, the BVH root) with it. At kBindingPixels it adds each pixel's samples into a
// vec4 (rgb = sum of the samples' radiance, w = 1 once the pixel's samples are all done).
GPU_CONST uint kBindingQuadLights = kBindingCount + 0u;   // GpuQuadLight[] (a texel buffer with the texel reads)
GPU_CONST uint kBindingPathParams = kBindingCount + 1u;   // GpuPathParams (a storage buffer, copied like params.glsl)
GPU_CONST uint kBindingEmitters = kBindingCount + 2u;     // GpuEmitter[] (a storage buffer in both read modes)
GPU_CONST uint kPathBindingCount = kBindingCount + 3u;

// Its own specialization constant ids, after the shared ones (gpu_render.h).
GPU_CONST uint kPathSpecHasQuadLights = kSpecSharedCount + 0u;
GPU_CONST uint kPathSpecHasGgx = kSpecSharedCount + 1u;          // some material has `brdf ggx`
// The render's integrator settings (the GpuPathParams members of the same names), so that the
// driver compiles out the code of the others: lavapipe runs every branch that any lane of a
// SIMD vector takes, and a value read from a buffer is unknown to it. kPathSpecFromParams (the default,
// and the value when not specializing) reads the setting from GpuPathParams instead.
GPU_CONST uint kPathSpecIntegrator = kSpecSharedCount + 2u;
GPU_CONST uint kPathSpecNextEvent = kSpecSharedCount + 3u;
GPU_CONST uint kPathSpecSampling = kSpecSharedCount + 4u;
GPU_CONST uint kPathSpecRussianRoulette = kSpecSharedCount + 5u;
GPU_CONST uint kPathSpecStratified = kSpecSharedCount + 6u;     // 1: lightStrata > 0 (`lightstratify on`)
GPU_CONST uint kPathSpecJitter = kSpecSharedCount + 7u;
GPU_CONST uint kPathSpecHasEmitters = kSpecSharedCount + 8u;    // some triangle or sphere emits (GpuEmitter): a feature, 0 or 1
// 1: stratified samples (GpuPathParams strataSide > 0), 0: independent ones.
GPU_CONST uint kPathSpecSampler = kSpecSharedCount + 9u;
GPU_CONST uint kPathSpecCount = kSpecSharedCount + 10u;
GPU_CONST uint kPathSpecFromParams = 0xFFFFFFFFu;

// GpuPathParams.maxDepth of `maxdepth -1`: no limit, only Russian roulette ends a path...
GPU_CONST uint kUnlimitedDepth = 0xFFFFFFFFu;
// ...or this many bounces (maxdepth -1 without Russian roulette in a closed scene of albedo 1
// has no end): where the generator's dimensions, bounce * kRngBounceStride, would wrap.
GPU_CONST uint kMaxBounces = 0xFFFFFFFFu / kRngBounceStride - 1u;
// A shadow ray toward a point x' on a quad light ends at this fraction of |x' - x|, so that
// the light's own triangles (at t = |x' - x|, up to rounding) never block it.
GPU_CONST float kQuadShadowSpan = 0.9990234375f;   // 1 - 2^-10

// One render's path settings, camera and sample range (a storage buffer, std430; pathtrace.comp
// copies it at its start, like params.glsl).
struct GpuPathParams {
  GpuCamera camera;
  uint integrator;          // kIntegratorAnalyticDirect, kIntegratorDirect or kIntegratorPathTracer
  uint nextEvent;           // kNextEventOff, On or Mis
  uint sampling;            // kSamplingHemisphere, Cosine or Brdf
  uint russianRoulette;     // 0 or 1
  uint maxDepth;            // D of doc/path-tracing.md, "Depth", or kUnlimitedDepth
  uint lightSamples;        // N per quad light per shading point
  uint lightStrata;         // sqrt(N) with `lightstratify on`, else 0
  uint quadLightCount;
  uint lightCount;          // point and directional lights
  uint seed;
  uint firstSample;         // this render's samples are [firstSample, firstSample + sampleCount)
  uint sampleCount;
  uint jitter;              // 0: every sample through the pixel centre (a render of spp 1); 1: uniform in the pixel
  uint emitterCount;        // entries of the GpuEmitter table (0: emissive surfaces are found by hitting only)
  float emitterWeightScale; // 1 / the emitters' total weight (GpuEmitter)
  uint strataSide;          // stratified samples (gpu_rng.h, rngStratify): side x side strata; 0: independent
  uint pad0, pad1, pad2;
  uint pad3;                // size 144
};
GPU_ASSERT_SIZE(GpuPathParams, 144)
GPU_ASSERT_OFFSET(GpuPathParams, integrator, 64)
GPU_ASSERT_OFFSET(GpuPathParams, maxDepth, 80)
GPU_ASSERT_OFFSET(GpuPathParams, seed, 100)
GPU_ASSERT_OFFSET(GpuPathParams, jitter, 112)
GPU_ASSERT_OFFSET(GpuPathParams, emitterWeightScale, 120)
GPU_ASSERT_OFFSET(GpuPathParams, strataSide, 124)

struct GpuPathPush {
  uint bandY0;              // first image row of this band
  uint resume;              // 0: every pixel starts its samples; 1: continue suspended pixels
  uint pad0, pad1;
};
GPU_ASSERT_SIZE(GpuPathPush, 16)

// Everything a suspended pixel of pathtrace.comp needs to continue where it stopped.
struct GpuPathTracerState {
  vec4 throughput;          // rgb path throughput T, w unused
  vec4 radiance;            // rgb radiance of this sample so far, w unused
  vec4 pixelSum;            // rgb sum of the pixel's finished samples, w = pdf of the last scatter (MIS)
  vec4 pending;             // rgb what the shadow ray adds when nothing blocks it, w unused
  uint bounce;              // path vertex: 0 at the camera ray's hit
  uint sampleIndex;         // samples of the current pixel finished
  uint tile;                // the current pixel's tile (pathtrace.comp: a lane renders one pixel of each tile of its run)
  uint pad0;                // size 80
  GpuTraceState trace;
};
GPU_ASSERT_SIZE(GpuPathTracerState, 80 + 112 + 8 * 96)
GPU_ASSERT_OFFSET(GpuPathTracerState, trace, 80)

GPU_END
#endif  // VKRT_GPU_PATH_H
