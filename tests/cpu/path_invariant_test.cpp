// The invariant of doc/path-tracing.md, "Estimators": next-event estimation (off, on, mis), Russian
// roulette, the sampling of directions (hemisphere, cosine, brdf), lightsamples and
// lightstratify change only the noise, never the expected image. One Cornell-like box (a quad
// light, Phong and GGX materials) is rendered with each strategy and compared with a
// reference strategy by per-block Welch t-tests, as Mitsuba 3's render tests do: the image is
// cut into 8x8-pixel blocks, each strategy renders K independent sample batches (different
// sample indices draw different numbers), and each block's and channel's batch means give a
// mean and its variance. A strategy fails when some block's p-value is below
// kAlpha / (blocks * channels) (Bonferroni): the chance that a correct strategy fails is at
// most kAlpha for a seed drawn at random (deterministic for the fixed seed here).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/path_reference.h"
#include "path_scenes.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"

namespace vkrt {
namespace {

constexpr int kSize = 32, kBlock = 8, kBatches = 16;
constexpr double kAlpha = 1e-3;
constexpr std::uint32_t kMirrorLobeSamples = 64;

struct Strategy {
  std::string name;
  NextEvent nee;
  Sampling sampling;
  bool roulette;
  int lightSamples;
  bool stratify;
  std::uint32_t samplesPerBatch;
};

// Per block and channel: the mean of the K batch means and the variance of that mean.
struct BlockStats {
  std::vector<double> mean, varianceOfMean;
};

BlockStats renderInBatches(const SceneDesc& scene, const Strategy& st, std::uint32_t seed) {
  SceneDesc s = scene;
  s.path.nextEvent = st.nee;
  s.path.sampling = st.sampling;
  s.path.russianRoulette = st.roulette;
  s.path.lightSamples = st.lightSamples;
  s.path.lightStratify = st.stratify;
  s.path.spp = static_cast<int>(st.samplesPerBatch) * kBatches;
  const Bvh bvh = buildBvh(s);
  const int blocksX = kSize / kBlock, cells = blocksX * blocksX * 3;
  std::vector<std::vector<double>> batchMeans(cells);
  for (int k = 0; k < kBatches; ++k) {
    PathOptions options;
    options.seed = seed;
    options.firstSample = k * st.samplesPerBatch;
    options.sampleCount = st.samplesPerBatch;
    RayCounts counts;
    const RadianceImage image = renderPathReference(s, bvh, options, &counts);
    EXPECT_EQ(counts.nonFinite, 0u) << st.name;
    std::vector<double> sums(cells, 0.0);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c) sums[((y / kBlock) * blocksX + x / kBlock) * 3 + c] += image.pixel(x, y)[c];
    for (int i = 0; i < cells; ++i) batchMeans[i].push_back(sums[i] / (kBlock * kBlock));
  }
  BlockStats stats;
  for (const auto& values : batchMeans) {
    double mean = 0.0, squares = 0.0;
    for (double v : values) mean += v;
    mean /= kBatches;
    for (double v : values) squares += (v - mean) * (v - mean);
    stats.mean.push_back(mean);
    stats.varianceOfMean.push_back(squares / (kBatches - 1) / kBatches);
  }
  return stats;
}

// The strategies compared with the reference (NEE on, cosine sampling, 4 stratified light
// samples: no BRDF sampling, no MIS weights, no roulette, so that a bug in any of those shows
// against it), each with its own seed.
const Strategy kReference{"on-cosine-ls4-stratified", NextEvent::On, Sampling::Cosine, false, 4, true, 16};
const std::vector<Strategy> kStrategies = {
    {"off-hemisphere", NextEvent::Off, Sampling::Hemisphere, false, 1, false, 16},
    {"off-cosine-rr", NextEvent::Off, Sampling::Cosine, true, 1, false, 16},
    {"off-brdf", NextEvent::Off, Sampling::Brdf, false, 1, false, 16},
    {"on-hemisphere-rr", NextEvent::On, Sampling::Hemisphere, true, 1, false, 4},
    {"on-cosine", NextEvent::On, Sampling::Cosine, false, 1, false, 4},
    {"on-brdf-ls4", NextEvent::On, Sampling::Brdf, false, 4, false, 4},
    {"mis-hemisphere", NextEvent::Mis, Sampling::Hemisphere, false, 1, false, 4},
    {"mis-cosine-rr", NextEvent::Mis, Sampling::Cosine, true, 1, false, 4},
    {"mis-brdf-rr-ls9-stratified", NextEvent::Mis, Sampling::Brdf, true, 9, true, 4},
};

void expectSameExpectation(const SceneDesc& scene, const std::vector<Strategy>& strategies,
                           const Strategy& referenceStrategy = kReference) {
  const int maxDepth = scene.maxDepth;
  const BlockStats reference = renderInBatches(scene, referenceStrategy, 1000);
  const std::size_t cells = reference.mean.size();
  const double threshold = kAlpha / static_cast<double>(cells);
  std::uint32_t seed = 1;
  for (const Strategy& st : strategies) {
    const BlockStats other = renderInBatches(scene, st, ++seed);
    double smallest = 1.0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < cells; ++i) {
      const double p = test::welchPValue(other.mean[i], other.varianceOfMean[i], kBatches, reference.mean[i],
                                         reference.varianceOfMean[i], kBatches);
      if (p < smallest) smallest = p, worst = i;
    }
    EXPECT_GE(smallest, threshold) << st.name << " (maxdepth " << maxDepth << "): block " << worst / 3 << " channel "
                                   << worst % 3 << " has mean " << other.mean[worst] << " +- "
                                   << std::sqrt(other.varianceOfMean[worst]) << " against the reference's "
                                   << reference.mean[worst] << " +- " << std::sqrt(reference.varianceOfMean[worst]);
  }
}

// Direct lighting plus two bounces: every strategy.
TEST(PathInvariant, EveryStrategyConvergesToTheSameImage) {
  expectSameExpectation(test::cornellLikeBox(kSize, 3), kStrategies);
}

// Direct lighting from a light as large and close as the glossy lobes are wide: light and
// BRDF sampling are then both good somewhere, and the MIS weights matter most.
TEST(PathInvariant, MisWeightsUnderALargeLight) {
  expectSameExpectation(test::glossyFloorUnderLargeLight(kSize), kStrategies);
}

// maxdepth -1: paths end by Russian roulette (the strategies with it) or not at all but by
// the bounce cap; only strategies with roulette are compared.
TEST(PathInvariant, UnlimitedDepthWithRussianRoulette) {
  std::vector<Strategy> withRoulette;
  for (const Strategy& st : kStrategies)
    if (st.roulette) withRoulette.push_back(st);
  expectSameExpectation(test::cornellLikeBox(kSize, -1), withRoulette);
}

// Emissive triangles and spheres found by hitting them (NEE off) and sampled as lights (on,
// mis) give one image.
TEST(PathInvariant, EmissiveSurfacesAsLights) {
  expectSameExpectation(test::emissiveSurfacesBox(kSize, 3), kStrategies);
}

// A diffuse floor beside a near-mirror Phong sphere (shininess 1000) and a small quad light,
// part of it lit only through the sphere (light -> sphere -> floor), maxdepth 2. With cosine
// sampling and NEE on, light reaching the floor through the sphere is found only by the
// light samples at the sphere (its sampled ray hitting the light counts nothing); with BRDF
// sampling and MIS mostly by that ray, weighted. Tolerance: the per-block Welch test of
// expectSameExpectation, p >= kAlpha / (blocks x channels) with the variances estimated from
// the 16 batches of 64 samples. (Deeper paths, in which the floor sees the lit floor through
// the lobe by cosine sampling, are heavy-tailed: bench/README.md, "Cosine sampling of a
// near-mirror lobe".)
TEST(PathInvariant, FloorSeesAMirrorLobeUnderASmallLight) {
  const Strategy misBrdf{"mis-brdf", NextEvent::Mis, Sampling::Brdf, false, 1, false, kMirrorLobeSamples};
  const Strategy onCosine{"on-cosine", NextEvent::On, Sampling::Cosine, false, 1, false, kMirrorLobeSamples};
  expectSameExpectation(test::floorBesideMirrorSphere(kSize, 2), {onCosine}, misBrdf);
}

TEST(WelchTest, StudentTailMatchesKnownValues) {
  // t = 2.131 with 15 degrees of freedom: two-sided 0.05; the normal limit at large dof.
  EXPECT_NEAR(test::studentTwoSidedTail(2.131449546, 15.0), 0.05, 1e-6);
  EXPECT_NEAR(test::studentTwoSidedTail(1.959963985, 1e7), 0.05, 1e-6);
  EXPECT_NEAR(test::studentTwoSidedTail(0.0, 4.0), 1.0, 1e-12);
}

}  // namespace
}  // namespace vkrt
