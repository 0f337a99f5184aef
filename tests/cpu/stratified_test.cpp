// Stratified samples (`--sampler stratified`, gpu_rng.h rngStratify): the first side^2
// samples of a pixel fill every stratum of each stratified pair once, every sample is still
// uniform on its own (so any number of samples is unbiased), and on a scene with edges and
// indirect light the error at equal samples drops against independent samples.
#include <algorithm>
#include <cmath>
#include <numeric>
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
  const std::uint32_t step = gpu::rngStrataStep(side);
  const float u = gpu::rngStratify(r, key, sample, dimension, side, step);
  const float v = gpu::rngStratify(r, key, sample, dimension + 1, side, step);
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
  for (std::uint32_t side : {2u, 3u, 7u, 8u, 10u, 256u}) {
    const std::uint32_t n = side * side, step = gpu::rngStrataStep(side);
    EXPECT_EQ(std::gcd(step, n), 1u) << side;
    EXPECT_GE(step, n / 4) << side;
    EXPECT_LE(step, n * 0.62) << side;
  }
}

// Samples 0 .. side^2 - 1 of a pixel: each stratum of each stratified pair exactly once,
// whatever the independent numbers (here 0, a half and 0.999; within 2^-24 of 1, float's
// cell + r rounds up to the next stratum's edge, as any float sum would); the other
// dimensions and later samples keep their independent numbers.
TEST(Stratified, TheFirstSamplesFillEveryStratumOnce) {
  for (std::uint32_t side : {2u, 5u, 8u, 16u}) {
    const std::uint32_t n = side * side;
    for (std::uint32_t pixel : {0u, 7u, 123456u})
      for (std::uint32_t dimension : {0u, 2u, 6u})
        for (float r : {0.0f, 0.5f, 0.999f}) {
          const std::uint32_t key = gpu::rngPixelKey(3, pixel);
          std::set<std::pair<std::uint32_t, std::uint32_t>> cells;
          for (std::uint32_t s = 0; s < n; ++s) cells.insert(cellOf(key, s, dimension, side, r));
          EXPECT_EQ(cells.size(), n) << "side " << side << " pixel " << pixel << " dimension " << dimension << " r " << r;
        }
    const std::uint32_t key = gpu::rngPixelKey(3, 7), step = gpu::rngStrataStep(side);
    for (std::uint32_t dimension : {4u, 5u, 8u, 65538u}) EXPECT_EQ(gpu::rngStratify(0.25f, key, 1, dimension, side, step), 0.25f);
    EXPECT_EQ(gpu::rngStratify(0.25f, key, n, 0, side, step), 0.25f) << "sample side^2: independent";
    EXPECT_EQ(gpu::rngStratify(0.25f, key, 1, 0, 0, 1), 0.25f) << "side 0: independent";
  }
}

// Any one sample, over many pixels, is uniform: its stratum is uniform (the permutation's
// offset is) and its place in the stratum too. 32768 pixels in 16 x 16 cells: the chi-square
// of the counts (255 degrees of freedom, mean 255, sd 22.6) stays under 380 (p < 1e-6), for
// the first, a middle and the last sample of the strata; and the two pairs' strata are
// independent (the camera's and the first bounce's).
TEST(Stratified, EverySampleIsUniformOnItsOwn) {
  const std::uint32_t side = 8, step = gpu::rngStrataStep(side), pixels = 32768;
  for (std::uint32_t sample : {0u, 29u, 63u}) {
    std::vector<int> counts(256, 0), joint(16 * 16, 0);
    for (std::uint32_t pixel = 0; pixel < pixels; ++pixel) {
      const std::uint32_t key = gpu::rngPixelKey(11, pixel);
      auto at = [&](std::uint32_t d) {
        return gpu::rngStratify(gpu::rngUniform(11, pixel, sample, d), key, sample, d, side, step);
      };
      const float u = at(0), v = at(1), du = at(2);
      ++counts[static_cast<int>(u * 16) * 16 + static_cast<int>(v * 16)];
      ++joint[static_cast<int>(u * 16) * 16 + static_cast<int>(du * 16)];
    }
    for (const std::vector<int>* c : {&counts, &joint}) {
      const double expected = pixels / 256.0;
      double chi2 = 0;
      for (int k : *c) chi2 += (k - expected) * (k - expected) / expected;
      EXPECT_LT(chi2, 380.0) << "sample " << sample;
    }
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
  auto mean = [](const RadianceImage& image) {
    double m = 0;
    for (float v : image.rgb) m += v;
    return m / static_cast<double>(image.rgb.size());
  };
  auto mse = [&](const RadianceImage& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) sum += (image.rgb[i] - reference.rgb[i]) * (image.rgb[i] - reference.rgb[i]);
    return sum / static_cast<double>(image.rgb.size());
  };
  const int seeds = 6;
  std::vector<double> means[2];
  double error[2] = {0, 0};
  for (std::uint32_t seed = 1; seed <= seeds; ++seed)
    for (int stratified = 0; stratified < 2; ++stratified) {
      RadianceImage image = render(16, seed, stratified == 1);
      error[stratified] += mse(image) / seeds;
      means[stratified].push_back(mean(image));
    }
  auto average = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); };
  double spread = 0;   // the independent renders' standard error of the mean
  for (double m : means[0]) spread += (m - average(means[0])) * (m - average(means[0]));
  spread = std::sqrt(spread / (seeds - 1) / seeds);
  std::printf("[ stats    ] MSE at 16 spp: independent %.4g, stratified %.4g (ratio %.3f); mean %.4g, %.4g, reference %.4g "
              "(standard error %.2g)\n", error[0], error[1], error[1] / error[0], average(means[0]), average(means[1]),
              mean(reference), spread);
  EXPECT_LT(error[1], 0.75 * error[0]);
  EXPECT_NEAR(average(means[1]), mean(reference), 4 * spread + 1e-3 * mean(reference));
  EXPECT_NEAR(average(means[0]), mean(reference), 4 * spread + 1e-3 * mean(reference));
}
