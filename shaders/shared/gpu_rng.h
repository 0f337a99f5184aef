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

// Stratified samples (`--sampler stratified`; doc/design.md, "Random numbers and sampling
// rules"). These pairs of dimensions are stratified across the samples of a pixel: the camera
// jitter (kRngPixelX/Y), and at every path vertex its direction (kRngSlotDirectionU/V) and its
// first light sample (the first two light slots). With `side` x `side` strata (side at most
// kRngMaxStrataSide; 0: none), sample s < side^2 of a pixel takes, in each pair p, the stratum
// (perm_p(s) + offset_p) mod side^2: perm_p a permutation of the strata and offset_p a number
// below side^2, both chosen by a hash of the pixel's key and p, so that the first side^2
// samples fill every stratum once, and different pairs' strata are not related; within the
// stratum, the pair's two independent numbers. Every sample is still uniform on its own (the
// offset is), so a render stopped after any number of samples is unbiased; samples from
// side^2 on are independent.
GPU_CONST uint kRngMaxStrataSide = 256u;        // side^2 stays below 2^32
GPU_CONST float kRngBelowOne = 0.99999994f;     // the largest float below 1
GPU_CONST uint kRngNotStratified = 0xFFFFFFFFu;

// The key of a pixel's strata permutation: the seed's and the pixel's, not the sample's.
GPU_FN uint rngPixelKey(uint seed, uint pixel) { return rngHash(pixel + rngHash(seed)); }

// The stratified pairs: the camera jitter's; at vertex b, its direction's (4 b + 1) and its
// first light sample's (4 b + 3).
GPU_CONST uint kRngCameraPair = 0u;
GPU_FN uint rngDirectionPair(uint bounce) { return 4u * bounce + 1u; }
GPU_FN uint rngLightPair(uint bounce) { return 4u * bounce + 3u; }

// The pair of `dimension` among the stratified ones, or kRngNotStratified.
GPU_FN uint rngStratifiedPair(uint dimension) {
  if (dimension < kRngBounceBase) return kRngCameraPair;
  uint bounce = (dimension - kRngBounceBase) / kRngBounceStride;
  uint slot = (dimension - kRngBounceBase) % kRngBounceStride;
  if (slot == kRngSlotDirectionU || slot == kRngSlotDirectionV) return rngDirectionPair(bounce);
  if (slot == kRngSlotLightBase || slot == kRngSlotLightBase + 1u) return rngLightPair(bounce);
  return kRngNotStratified;
}

// A permutation of 0 .. n-1 chosen by `key`, at i < n: the hash-based permutation of Kensler
// ("Correlated Multi-Jittered Sampling", Pixar technical memo 13-01, 2013): invertible steps
// on the bits of the next power of two, repeated while the value falls outside [0, n).
GPU_FN uint rngPermute(uint i, uint n, uint key) {
  uint w = n - 1u;
  w |= w >> 1u;
  w |= w >> 2u;
  w |= w >> 4u;
  w |= w >> 8u;
  w |= w >> 16u;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16u;
    i ^= (i & w) >> 4u;
    i ^= key >> 8u;
    i *= 0x0929eb3fu;
    i ^= key >> 23u;
    i ^= (i & w) >> 1u;
    i *= 1u | key >> 27u;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11u;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2u;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2u;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5u;
  } while (i >= n);
  return i;
}

// The stratum of `pair` for global sample `sampleIndex` of the pixel whose key is `pixelKey`,
// or kRngNotStratified where that sample is not stratified (side 0, or sample side^2 on).
GPU_FN uint rngPairStratum(uint pixelKey, uint sampleIndex, uint pair, uint side) {
  uint n = side * side;
  if (side == 0u || sampleIndex >= n) return kRngNotStratified;
  uint key = rngHash(pair + pixelKey);
  return (rngPermute(sampleIndex, n, key) + rngHash(key) % n) % n;
}

// A pair's stratum as its two cells: x for the pair's even dimension, y for the odd one.
GPU_FN uint rngStratumCell(uint stratum, uint dimension, uint side) {
  return (dimension & 1u) == 0u ? stratum % side : stratum / side;
}

// The independent number `r` moved into cell `cell` of `side`.
GPU_FN float rngInCell(float r, uint cell, uint side) {
  float x = (float(cell) + r) / float(side);
  return x < kRngBelowOne ? x : kRngBelowOne;
}

// The number of `dimension` for global sample `sampleIndex` of the pixel whose key is
// `pixelKey`, given that dimension's independent number `r`: r itself outside the strata.
// (pathtrace.comp computes the strata once per sample and vertex, and then rngInCell.)
GPU_FN float rngStratify(float r, uint pixelKey, uint sampleIndex, uint dimension, uint side) {
  uint pair = rngStratifiedPair(dimension);
  if (pair == kRngNotStratified) return r;
  uint stratum = rngPairStratum(pixelKey, sampleIndex, pair, side);
  if (stratum == kRngNotStratified) return r;
  return rngInCell(r, rngStratumCell(stratum, dimension, side), side);
}

// The strata of a render of `spp` samples: side = floor(sqrt(spp)), at most
// kRngMaxStrataSide (0 for one sample: nothing to stratify).
GPU_FN uint rngStrataSide(uint spp) {
  uint side = 0u;
  while (side < kRngMaxStrataSide && (side + 1u) * (side + 1u) <= spp) side += 1u;
  return side < 2u ? 0u : side;
}
GPU_END
#endif  // VKRT_GPU_RNG_H
