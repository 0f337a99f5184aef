// The random numbers of one camera sample on the CPU reference: the generator and the
// dimensions of gpu_rng.h, keyed by seed, pixel and sample, stratified as the shader's.
#pragma once

#include <cstdint>

#include "gpu_types.h"

namespace vkrt {

struct SampleNumbers {
  std::uint32_t seed, pixel, sample;
  std::uint32_t strataSide = 0;   // stratified samples (gpu_rng.h); side 0: none

  double at(std::uint32_t dimension) const {
    const float r = gpu::rngUniform(seed, pixel, sample, dimension);
    if (strataSide == 0) return r;
    return gpu::rngStratify(r, gpu::rngPixelKey(seed, pixel), sample, dimension, strataSide);
  }

  // The number of `slot` at path vertex `bounce`. A vertex has kRngBounceStride slots, all
  // that the Vulkan backend takes (it refuses more light samples). The CPU reference takes
  // more, and their slots would run into the next vertex's dimensions (its direction,
  // roulette and light samples, the same numbers again): slots from kRngBounceStride on draw
  // from a stream of their own for each vertex and each run of kRngBounceStride slots,
  // independent and never stratified.
  double at(std::uint32_t bounce, std::uint64_t slot) const {
    if (slot < gpu::kRngBounceStride) return at(gpu::rngDimension(bounce, static_cast<std::uint32_t>(slot)));
    const std::uint32_t run = static_cast<std::uint32_t>(slot / gpu::kRngBounceStride);
    const std::uint32_t key = gpu::rngHash(gpu::rngSampleKey(seed, pixel, sample) ^ gpu::rngHash(bounce + gpu::rngHash(run)));
    return gpu::rngUniformKeyed(key, static_cast<std::uint32_t>(slot % gpu::kRngBounceStride));
  }
};

// The slots of gpu_rng.h's light samples, in 64 bits: light sample k of n of quad light j
// (its u; v is the next slot), and an emitter light sample's point and pick
// (gpu::rngEmitterPointSlot, gpu::rngEmitterPickSlot, which wrap past 2^32).
inline std::uint64_t quadLightSlot(std::uint64_t j, std::uint64_t n, std::uint64_t k) {
  return gpu::kRngSlotLightBase + 2 * (j * n + k);
}
inline std::uint64_t emitterPointSlot(std::uint64_t quads, std::uint64_t n, std::uint64_t k) {
  return gpu::kRngSlotLightBase + 2 * (quads * n + k);
}
inline std::uint64_t emitterPickSlot(std::uint64_t quads, std::uint64_t n, std::uint64_t k) {
  return gpu::kRngSlotLightBase + 2 * (quads + 1) * n + k;
}

}  // namespace vkrt
