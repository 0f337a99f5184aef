// The CPU renderers' tiling (host/cpu/pixel_tiles.h): every pixel of a region shaded exactly
// once on any number of threads and stored at its place, the progress it reports, the ray
// counts it sums, non-finite colours counted and stored finite, and stopping between tiles.
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/pixel_tiles.h"

namespace vkrt {
namespace {

constexpr float kFloatMax = std::numeric_limits<float>::max();

// A colour that names its pixel.
dvec3 colourOf(int x, int y) { return dvec3(x, y, 0.5 * x + 1000.0 * y); }

TEST(PixelTiles, EveryPixelOfTheRegionIsShadedOnceAndStoredInPlace) {
  const int fullW = 70, fullH = 50;
  const PixelRect regions[] = {{0, 0, 70, 50}, {0, 0, 1, 1}, {3, 5, 20, 38}, {16, 16, 32, 32}, {69, 0, 70, 50},
                               {5, 49, 70, 50}, {10, 10, 10, 30}};
  for (const PixelRect& region : regions)
    for (int threads : {1, 2, 3, 8, 0}) {
      std::unique_ptr<std::atomic<int>[]> calls(new std::atomic<int>[fullW * fullH]);
      for (int i = 0; i < fullW * fullH; ++i) calls[i] = 0;
      RadianceImage image(region.width(), region.height());
      shadeTiles(
          region, threads, 1,
          [&](int x, int y, RayCounts&) {
            EXPECT_TRUE(x >= 0 && x < fullW && y >= 0 && y < fullH) << x << ", " << y;
            if (x >= 0 && x < fullW && y >= 0 && y < fullH) ++calls[y * fullW + x];
            return colourOf(x, y);
          },
          image, nullptr, nullptr, nullptr);
      for (int y = 0; y < fullH; ++y)
        for (int x = 0; x < fullW; ++x) {
          const bool inside = x >= region.x0 && x < region.x1 && y >= region.y0 && y < region.y1;
          ASSERT_EQ(calls[y * fullW + x], inside ? 1 : 0)
              << "pixel " << x << ", " << y << " of region " << region.x0 << "," << region.y0 << " - "
              << region.x1 << "," << region.y1 << " on " << threads << " threads";
          if (!inside) continue;
          const float* p = image.pixel(x - region.x0, y - region.y0);
          const dvec3 c = colourOf(x, y);
          ASSERT_EQ(p[0], static_cast<float>(c.x));
          ASSERT_EQ(p[1], static_cast<float>(c.y));
          ASSERT_EQ(p[2], static_cast<float>(c.z));
        }
    }
}

TEST(PixelTiles, ProgressRisesToTheRegionsUnits) {
  const PixelRect region{2, 3, 41, 37};   // 39 x 34: tiles of 16 and a remainder each way
  for (int threads : {1, 4}) {
    for (std::uint64_t units : {std::uint64_t{1}, std::uint64_t{7}}) {
      RadianceImage image(region.width(), region.height());
      std::vector<std::pair<std::uint64_t, std::uint64_t>> reports;
      std::mutex m;
      shadeTiles(
          region, threads, units, [](int, int, RayCounts&) { return dvec3(0.0); }, image,
          [&](std::uint64_t done, std::uint64_t total) {
            std::lock_guard lock(m);
            reports.emplace_back(done, total);
          },
          nullptr, nullptr);
      const std::uint64_t total = 39ull * 34ull * units;
      ASSERT_EQ(reports.size(), 9u);   // one per tile: 3 x 3
      for (std::size_t i = 0; i < reports.size(); ++i) {
        EXPECT_EQ(reports[i].second, total);
        if (i > 0) {
          EXPECT_GT(reports[i].first, reports[i - 1].first);
        }
      }
      EXPECT_EQ(reports.back().first, total);
    }
  }
}

TEST(PixelTiles, TheWorkersRayCountsAreSummed) {
  const PixelRect region{0, 0, 33, 20};
  for (int threads : {1, 5}) {
    RadianceImage image(region.width(), region.height());
    RayCounts counts;
    shadeTiles(
        region, threads, 1,
        [](int x, int y, RayCounts& local) {
          ++local.primary;
          local.shadow += static_cast<std::uint64_t>(x);
          local.secondary += static_cast<std::uint64_t>(y);
          return dvec3(0.0);
        },
        image, nullptr, nullptr, &counts);
    EXPECT_EQ(counts.primary, 33u * 20u);
    EXPECT_EQ(counts.shadow, 20u * (32u * 33u / 2u));   // each row: 0 + 1 + ... + 32
    EXPECT_EQ(counts.secondary, 33u * (19u * 20u / 2u));
    EXPECT_EQ(counts.nonFinite, 0u);
  }
}

TEST(PixelTiles, NonFiniteColoursAreCountedAndStoredFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const dvec3 colours[] = {dvec3(1, 2, 3), dvec3(nan, 0, 0), dvec3(0, inf, 0), dvec3(0, 0, -1e39),
                           dvec3(3.4e38, -3.4e38, 0)};   // the last is within float: not counted
  const PixelRect region{0, 0, 5, 1};
  RadianceImage image(5, 1);
  RayCounts counts;
  shadeTiles(region, 2, 1, [&](int x, int, RayCounts&) { return colours[x]; }, image, nullptr, nullptr, &counts);
  EXPECT_EQ(counts.nonFinite, 3u);
  for (float v : image.rgb) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(image.pixel(1, 0)[0], 0.0f);
  EXPECT_EQ(image.pixel(2, 0)[1], kFloatMax);
  EXPECT_EQ(image.pixel(3, 0)[2], -kFloatMax);
  EXPECT_EQ(image.pixel(4, 0)[0], 3.4e38f);
}

TEST(PixelTiles, ToFloatRoundsToNearestAndClampsToFloatsRange) {
  EXPECT_EQ(toFloat(0.5), 0.5f);
  EXPECT_EQ(toFloat(0.1), 0.1f);
  EXPECT_EQ(toFloat(1.0 + 0x1p-24), 1.0f);              // a tie: to even
  EXPECT_EQ(toFloat(1.0 + 0x1p-24 + 0x1p-40), 1.0f + 0x1p-23f);
  EXPECT_EQ(toFloat(1e300), kFloatMax);
  EXPECT_EQ(toFloat(-1e300), -kFloatMax);
  EXPECT_EQ(toFloat(std::numeric_limits<double>::infinity()), kFloatMax);
  EXPECT_EQ(toFloat(-std::numeric_limits<double>::infinity()), -kFloatMax);
  EXPECT_EQ(toFloat(std::numeric_limits<double>::quiet_NaN()), 0.0f);
}

TEST(PixelTiles, StopIsPolledBetweenTiles) {
  const PixelRect region{0, 0, 64, 64};   // 16 tiles
  RadianceImage image(64, 64);
  std::atomic<int> shaded{0};
  auto shade = [&](int, int, RayCounts&) {
    ++shaded;
    return dvec3(1.0);
  };
  shadeTiles(region, 3, 1, shade, image, nullptr, [] { return true; }, nullptr);
  EXPECT_EQ(shaded, 0);
  // Stopping after the first tile on one thread: exactly that tile's 256 pixels.
  int polls = 0;
  shadeTiles(region, 1, 1, shade, image, nullptr, [&] { return ++polls > 1; }, nullptr);
  EXPECT_EQ(shaded, 256);
}

}  // namespace
}  // namespace vkrt
