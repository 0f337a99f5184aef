// gpu_rng.h: the random numbers of the path integrators, the same on both backends: which
// number each use draws, and the generator.
#ifndef VKRT_GPU_RNG_H
#define VKRT_GPU_RNG_H

#include "gpu_prelude.h"

GPU_BEGIN

// A counter-based generator.
// The number for (seed, pixel, sample, dimension) is a hash of the four: a render is
// reproducible bit for bit whatever the order in which pixels and samples are computed, a
// crop draws the numbers of the full image (pixel = y * full width + x), sample batches of
// one render draw different numbers (sample counts from the render's first sample), and the
// CPU reference and the shader draw the same numbers for the same path.
// Dimensions: kRngPixelX/Y jitter the camera ray inside its pixel; each path vertex (bounce
// b = 0 at the primary hit) then uses b * kRngBounceStride + a slot:
GPU_CONST uint kRngPixelX = 0u;
GPU_CONST uint kRngPixelY = 1u;
GPU_CONST uint kRngBounceStride = 65536u;
GPU_CONST uint kRngBounceBase = 2u;           // + b * kRngBounceStride
GPU_CONST uint kRngSlotDirectionU = 0u;       // the next direction (two numbers)
GPU_CONST uint kRngSlotDirectionV = 1u;
GPU_CONST uint kRngSlotLobe = 2u;             // which lobe of a BRDF-sampling mixture
GPU_CONST uint kRngSlotRoulette = 3u;         // Russian roulette
GPU_CONST uint kRngSlotLightBase = 4u;        // + 2 * (light * lightsamples + k): a light sample's u, v

// How each backend turns these numbers into a path (camera jitter, directions, lobes, light
// and emitter samples, roulette): doc/design.md, "Random numbers and sampling rules"; the
// shader (brdf.glsl, pathtrace.comp) and the CPU reference (host/cpu/path_reference.cpp) are
// each written to those rules on their own.

// The slots of emitter light sample k of N at a vertex with `quads` quad lights: the point's
// two numbers (slot, slot + 1) follow the quad lights' pairs, the picks follow those.
GPU_FN uint rngEmitterPointSlot(uint quads, uint n, uint k) { return kRngSlotLightBase + 2u * (quads * n + k); }
GPU_FN uint rngEmitterPickSlot(uint quads, uint n, uint k) { return kRngSlotLightBase + 2u * (quads + 1u) * n + k; }

// "lowbias32" (C. Wellons, 2018): an integer hash with small bias, cheap on any ISA.
GPU_FN uint rngHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

// The hash of (seed, pixel, sample): what the numbers of one sample share (a shader computes
// it once per sample).
GPU_FN uint rngSampleKey(uint seed, uint pixel, uint sampleIndex) {
  return rngHash(sampleIndex + rngHash(pixel + rngHash(seed)));
}

// The number of `dimension` in the sample whose key is `key`: rngUniform's, bit for bit.
GPU_FN float rngUniformKeyed(uint key, uint dimension) {
  return float(rngHash(dimension + key) >> 8u) * 5.9604644775390625e-8f;   // 2^-24
}

// A uniform number in [0, 1): 24 random bits, so it is exact in float and never 1.
GPU_FN float rngUniform(uint seed, uint pixel, uint sampleIndex, uint dimension) {
  return rngUniformKeyed(rngSampleKey(seed, pixel, sampleIndex), dimension);
}

// The dimension of `slot` at path vertex `bounce`.
GPU_FN uint rngDimension(uint bounce, uint slot) { return kRngBounceBase + bounce * kRngBounceStride + slot; }

GPU_END
#endif  // VKRT_GPU_RNG_H
