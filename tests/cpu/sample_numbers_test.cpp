// The CPU reference's random numbers (cpu/sample_numbers.h): the shader's numbers bit for bit
// within a vertex's kRngBounceStride slots, and numbers of their own beyond them (light
// samples that the Vulkan backend refuses), not the next vertex's again.
#include <cmath>
#include <cstdint>
#include <set>

#include <gtest/gtest.h>

#include "cpu/sample_numbers.h"
#include "gpu_rng.h"

using namespace vkrt;

TEST(SampleNumbers, WithinAVertexTheyAreTheShaders) {
  for (std::uint32_t side : {0u, 4u}) {
    const SampleNumbers rng{7, 1234, 5, side};
    for (std::uint32_t bounce : {0u, 1u, 4u})
      for (std::uint32_t slot : {0u, 1u, 3u, 4u, 5u, 1000u, 65534u, 65535u}) {
        const std::uint32_t d = gpu::rngDimension(bounce, slot);
        float r = gpu::rngUniform(7, 1234, 5, d);
        if (side > 0) r = gpu::rngStratify(r, gpu::rngPixelKey(7, 1234), 5, d, side);
        EXPECT_EQ(rng.at(bounce, std::uint64_t{slot}), static_cast<double>(r)) << bounce << " " << slot;
      }
  }
  // The slots of gpu_rng.h, where they fit in 32 bits.
  EXPECT_EQ(emitterPointSlot(3, 5, 2), gpu::rngEmitterPointSlot(3, 5, 2));
  EXPECT_EQ(emitterPickSlot(3, 5, 2), gpu::rngEmitterPickSlot(3, 5, 2));
  EXPECT_EQ(quadLightSlot(2, 9, 4), gpu::kRngSlotLightBase + 2u * (2u * 9u + 4u));
  EXPECT_EQ(quadLightSlot(3, 2000000000, 5), 4 + 2 * (6000000000ull + 5));   // past 2^32: no wrap
}

// Light samples past a vertex's slots (lightsamples 40,000 of one quad light: slots up to
// 80,003): before, slot 65536 + s of vertex b was slot s of vertex b + 1, so those light
// samples repeated the next vertex's direction, roulette and light numbers.
TEST(SampleNumbers, BeyondAVertexsSlotsTheyAreNotTheNextVertexs) {
  for (std::uint32_t side : {0u, 4u}) {
    const SampleNumbers rng{7, 99, 3, side};
    int same = 0;
    std::set<double> seen;
    double sum = 0.0;
    const int n = 20000;
    for (std::uint32_t bounce = 0; bounce < 3; ++bounce)
      for (std::uint64_t s = 0; s < static_cast<std::uint64_t>(n); ++s) {
        const double beyond = rng.at(bounce, gpu::kRngBounceStride + s);
        same += beyond == rng.at(bounce + 1, s);
        same += beyond == rng.at(bounce, s);
        same += beyond == rng.at(bounce, 2 * std::uint64_t{gpu::kRngBounceStride} + s);   // the run after it
        EXPECT_GE(beyond, 0.0);
        EXPECT_LT(beyond, 1.0);
        seen.insert(beyond);
        sum += beyond;
      }
    // Independent numbers of 24 bits: a coincidence of two is about 1 in 16 million per pair.
    EXPECT_LE(same, 2) << side;
    // (60,000 numbers of 24 bits share about 107 values by chance.)
    EXPECT_GE(seen.size(), static_cast<std::size_t>(3 * n - 300));
    // Uniform: the mean of 60,000 within 5 standard deviations (0.29 / sqrt(60,000)).
    EXPECT_NEAR(sum / (3 * n), 0.5, 5 * 0.2887 / std::sqrt(3.0 * n));
  }
}
