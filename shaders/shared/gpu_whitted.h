// gpu_whitted.h: raytrace.comp's own interface (the Whitted model): its specialization ids,
// the exactness cut-off, its push constants and its suspended state.
#ifndef VKRT_GPU_WHITTED_H
#define VKRT_GPU_WHITTED_H

#include "gpu_render.h"

GPU_BEGIN

// raytrace.comp's own specialization constant ids, after the shared ones.
GPU_CONST uint kSpecHasSpecular = kSpecSharedCount + 0u;   // highlights and mirror rays
GPU_CONST uint kSpecCutoff = kSpecSharedCount + 1u;        // the exactness cut-off of the mirror loop (GpuCutoff)
GPU_CONST uint kSpecCount = kSpecSharedCount + 2u;

// raytrace.comp's exactness cut-off: a mirror ray is not traced when the most that the rest
// of the path can add or take away, |throughput| * bound * (1 + s + s^2 + ...) per channel
// (s = specular), leaves every channel's byte as it is. bound bounds the |radiance| that one
// hit can send (ambient + emission + every light at full strength); +infinity where there is
// no bound (a point light without a constant attenuation term), and the shader never cuts by
// such a channel (flatten.cpp, cutoffConstants).
struct GpuCutoff {
  vec4 bound;               // rgb = that bound per channel; w = 1 when no colour or attenuation term is negative
  vec4 specular;            // rgb = the largest |specular| of any material, per channel; w unused
};
GPU_ASSERT_SIZE(GpuCutoff, 32)

struct GpuPushConstants {
  GpuCamera camera;
  GpuCutoff cutoff;
  uint bandY0;              // first image row of this band
  uint resume;              // 0: every pixel starts fresh; 1: continue suspended pixels
  uint pad0, pad1;          // size 112 (push constants: at most 128 bytes)
};
GPU_ASSERT_SIZE(GpuPushConstants, 112)
GPU_ASSERT_OFFSET(GpuPushConstants, cutoff, 64)
GPU_ASSERT_OFFSET(GpuPushConstants, bandY0, 96)

// Everything a suspended invocation of raytrace.comp needs to continue where it stopped.
struct GpuWhittedState {
  vec4 throughput;          // rgb weight of the current segment, w unused
  vec4 radiance;            // rgb sum so far, w unused
  vec4 lightColor;          // rgb light colour / attenuation of the current shadow ray, w unused
  uint depth;               // mirror reflections so far
  uint tile;                // the tile of the band whose pixel the invocation computes
  uint pad0, pad1;          // size 64
  GpuTraceState trace;
};
GPU_ASSERT_SIZE(GpuWhittedState, 64 + 112 + 8 * 96)
GPU_ASSERT_OFFSET(GpuWhittedState, trace, 64)

GPU_END
#endif  // VKRT_GPU_WHITTED_H
