// Stratified samples (`--sampler stratified`, gpu_rng.h rngStratify): the first side^2
// samples of a pixel fill every stratum of each stratified pair once, every sample is still
// uniform on its own (so any number of samples is unbiased), and on a scene with edges and
// indirect light the error at equal samples drops against independent samples.
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "cpu/path_reference.h"
#include "scene/bvh.h"
#include "scene/parse.h"
#include "gpu_rng.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

// The stratum (column, row) that `sample`'s numbers of pair (dimension, dimension + 1) land
// in, their independent numbers being r.
std::pair<std::uint32_t, std::uint32_t> cellOf(std::uint32_t key, std::uint32_t sample, std::uint32_t dimension,
                                               std::uint32_t side, float r) {
  const float u = gpu::rngStratify(r, key, sample, dimension, side);
  const float v = gpu::rngStratify(r, key, sample, dimension + 1, side);
  EXPECT_GE(u, 0.0f);
  EXPECT_LT(u, 1.0f);
  EXPECT_LT(v, 1.0f);
  return {static_cast<std::uint32_t>(u * static_cast<float>(side)), static_cast<std::uint32_t>(v * static_cast<float>(side))};
}

}  // namespace

TEST(Stratified, StrataOfARender) {
  EXPECT_EQ(gpu::rngStrataSide(1), 0u);
  EXPECT_EQ(gpu::rngStrataSide(3), 0u);   // one stratum: nothing to stratify
  EXPECT_EQ(gpu::rngStrataSide(4), 2u);
  EXPECT_EQ(gpu::rngStrataSide(63), 7u);
  EXPECT_EQ(gpu::rngStrataSide(64), 8u);
  EXPECT_EQ(gpu::rngStrataSide(1u << 30), gpu::kRngMaxStrataSide);
}

// rngPermute is a permutation of 0 .. n-1 for every n (powers of two and not) and key, and
// different keys give different orders.
TEST(Stratified, PermuteIsAPermutation) {
  for (std::uint32_t n : {1u, 2u, 3u, 4u, 25u, 49u, 64u, 100u, 65536u})
    for (std::uint32_t key : {0u, 1u, 0x9e3779b9u, 0xffffffffu}) {
      std::vector<bool> seen(n, false);
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = gpu::rngPermute(i, n, key);
        ASSERT_LT(j, n) << "n " << n << " key " << key;
        EXPECT_FALSE(seen[j]) << "n " << n << " key " << key << ": " << j << " twice";
        seen[j] = true;
      }
    }
  int same = 0;
  for (std::uint32_t i = 0; i < 64; ++i) same += gpu::rngPermute(i, 64, 1) == gpu::rngPermute(i, 64, 2);
  EXPECT_LT(same, 8);
}

// Samples 0 .. side^2 - 1 of a pixel: each stratum of each stratified pair exactly once (the
// camera jitter, and at bounces 0, 1 and 4 the direction and the first light sample),
// whatever the independent numbers (here 0, a half and 0.999; within 2^-24 of 1, float's
// cell + r rounds up to the next stratum's edge, as any float sum would); the other
// dimensions and later samples keep their independent numbers.
TEST(Stratified, TheFirstSamplesFillEveryStratumOnce) {
  const std::uint32_t bounce1 = gpu::kRngBounceStride, bounce4 = 4 * gpu::kRngBounceStride;
  for (std::uint32_t side : {2u, 5u, 8u, 16u}) {
    const std::uint32_t n = side * side;
    for (std::uint32_t pixel : {0u, 7u, 123456u})
      for (std::uint32_t dimension : {0u, 2u, 6u, 2u + bounce1, 6u + bounce1, 2u + bounce4, 6u + bounce4})
        for (float r : {0.0f, 0.5f, 0.999f}) {
          const std::uint32_t key = gpu::rngPixelKey(3, pixel);
          std::set<std::pair<std::uint32_t, std::uint32_t>> cells;
          for (std::uint32_t s = 0; s < n; ++s) cells.insert(cellOf(key, s, dimension, side, r));
          EXPECT_EQ(cells.size(), n) << "side " << side << " pixel " << pixel << " dimension " << dimension << " r " << r;
        }
    const std::uint32_t key = gpu::rngPixelKey(3, 7);
    for (std::uint32_t dimension : {4u, 5u, 8u, 9u, 4u + bounce1, 5u + bounce1, 8u + bounce4})
      EXPECT_EQ(gpu::rngStratify(0.25f, key, 1, dimension, side), 0.25f) << dimension;
    EXPECT_EQ(gpu::rngStratify(0.25f, key, n, 0, side), 0.25f) << "sample side^2: independent";
    EXPECT_EQ(gpu::rngStratify(0.25f, key, 1, 0, 0), 0.25f) << "side 0: independent";
  }
}

// Any one sample, over many pixels, is uniform: its stratum is uniform (the permutation's
// offset is) and its place in the stratum too. 32768 pixels in 16 x 16 cells: the chi-square
// of the counts (255 degrees of freedom, mean 255, sd 22.6) stays under 380 (p < 1e-6), for
// the first, a middle and the last sample of the strata; and two pairs' strata are
// independent (the camera's and the first and second bounces' directions).
TEST(Stratified, EverySampleIsUniformOnItsOwn) {
  const std::uint32_t side = 8, pixels = 32768;
  for (std::uint32_t sample : {0u, 29u, 63u}) {
    std::vector<int> counts(256, 0), joint(16 * 16, 0), deeper(16 * 16, 0);
    for (std::uint32_t pixel = 0; pixel < pixels; ++pixel) {
      const std::uint32_t key = gpu::rngPixelKey(11, pixel);
      auto at = [&](std::uint32_t d) {
        return gpu::rngStratify(gpu::rngUniform(11, pixel, sample, d), key, sample, d, side);
      };
      const float u = at(0), v = at(1), du = at(2), du1 = at(2 + gpu::kRngBounceStride);
      ++counts[static_cast<int>(u * 16) * 16 + static_cast<int>(v * 16)];
      ++joint[static_cast<int>(u * 16) * 16 + static_cast<int>(du * 16)];
      ++deeper[static_cast<int>(du * 16) * 16 + static_cast<int>(du1 * 16)];
    }
    for (const std::vector<int>* c : {&counts, &joint, &deeper}) {
      const double expected = pixels / 256.0;
      double chi2 = 0;
      for (int k : *c) chi2 += (k - expected) * (k - expected) / expected;
      EXPECT_LT(chi2, 380.0) << "sample " << sample;
    }
  }
}

// Within one pixel, two pairs' strata are not tied to each other: were they (for example one
// order shifted for each pair), the stratum of one would tell the other's, and a path's
// directions at successive bounces would move together from sample to sample. Over a
// pixel's 64 samples the difference of the two strata (mod 64) takes about 64 (1 - 1/e) = 40
// values for unrelated orders, one for shifted ones; here at least 24 on average.
TEST(Stratified, PairsAreNotTiedToEachOther) {
  const std::uint32_t side = 8, n = 64;
  const std::uint32_t pairs[][2] = {{0, 2}, {2, 2 + gpu::kRngBounceStride}, {2, 6}, {6, 6 + gpu::kRngBounceStride}};
  for (const auto& dims : pairs) {
    double distinct = 0;
    for (std::uint32_t pixel = 0; pixel < 100; ++pixel) {
      const std::uint32_t key = gpu::rngPixelKey(5, pixel);
      std::set<std::uint32_t> differences;
      for (std::uint32_t s = 0; s < n; ++s) {
        auto stratum = [&](std::uint32_t d) {
          const auto [x, y] = cellOf(key, s, d, side, 0.5f);
          return y * side + x;
        };
        differences.insert((stratum(dims[1]) + n - stratum(dims[0])) % n);
      }
      distinct += static_cast<double>(differences.size()) / 100.0;
    }
    EXPECT_GT(distinct, 24.0) << "dimensions " << dims[0] << " and " << dims[1];
  }
}

// The CPU reference on the project's Cornell box (scenes/gi/box.test: edges, indirect light,
// MIS) at 64x64, a 24x24 crop at its centre, 16 samples, 6 seeds each way, against 1024
// independent samples: stratified samples' mean squared error is below 0.75 of independent
// ones' (measured: 0.65), and their mean radiance agrees with the reference's as well
// as independent samples' does (within 4 of their standard errors: no bias).
TEST(Stratified, LessErrorAtEqualSamplesAndNoBias) {
  SceneDesc scene = parseSceneFile(sourcePath("scenes/gi/box.test"));
  scene.width = scene.height = 64;
  const PixelRect crop{20, 20, 44, 44};
  Bvh bvh = buildBvh(scene);
  auto render = [&](std::uint32_t spp, std::uint32_t seed, bool stratified) {
    SceneDesc s = scene;
    s.path.spp = static_cast<int>(spp);
    PathOptions o;
    o.seed = seed;
    o.crop = crop;
    o.stratified = stratified;
    return renderPathReference(s, bvh, o, nullptr);
  };
  const RadianceImage reference = render(1024, 1000, false);
  const EstimatorComparison c =
      compareEstimators(reference, 6, [&](int stratified, std::uint32_t seed) { return render(16, seed, stratified == 1); });
  expectLessNoiseSameMean(c, reference, 0.75, "independent (16 spp)", "stratified");
}
