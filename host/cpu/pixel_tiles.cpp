#include "cpu/pixel_tiles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "util/parallel_for.h"

namespace vkrt {
namespace {

constexpr int kTile = 16;

}  // namespace

float toFloat(double c) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (std::isnan(c)) return 0.0f;
  return static_cast<float>(std::clamp(c, -kMax, kMax));
}

void shadeTiles(const PixelRect& region, int threads, std::uint64_t unitsPerPixel,
                const std::function<dvec3(int x, int y, RayCounts& counts)>& shade, RadianceImage& image,
                const std::function<void(std::uint64_t, std::uint64_t)>& progress, const std::function<bool()>& stop,
                RayCounts* counts) {
  const int tilesX = (region.width() + kTile - 1) / kTile, tilesY = (region.height() + kTile - 1) / kTile;
  const int tileCount = tilesX * tilesY;
  const std::uint64_t total = static_cast<std::uint64_t>(region.width()) * region.height() * unitsPerPixel;
  std::mutex mutex;   // guards done, the progress callback and the totals
  std::uint64_t done = 0;
  RayCounts totals;

  auto shadeTile = [&](std::size_t tile) {
    RayCounts local;
    // (x, y): the full image's pixel; its place in `image` is relative to the region.
    const int t = static_cast<int>(tile);
    int x0 = region.x0 + (t % tilesX) * kTile, y0 = region.y0 + (t / tilesX) * kTile;
    int x1 = std::min(x0 + kTile, region.x1), y1 = std::min(y0 + kTile, region.y1);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const dvec3 c = shade(x, y, local);
        float* px = image.pixel(x - region.x0, y - region.y0);
        for (int k = 0; k < 3; ++k) px[k] = toFloat(c[k]);
        // As the shader counts: a channel NaN or beyond float32 (which it computes in).
        constexpr double kMax = std::numeric_limits<float>::max();
        if (!(std::abs(c.x) <= kMax && std::abs(c.y) <= kMax && std::abs(c.z) <= kMax)) ++local.nonFinite;
      }
    std::lock_guard lock(mutex);
    done += static_cast<std::uint64_t>(x1 - x0) * (y1 - y0) * unitsPerPixel;
    if (progress) progress(done, total);
    totals += local;
  };
  parallelFor(static_cast<std::size_t>(tileCount), threads > 0 ? static_cast<unsigned>(threads) : 0u, shadeTile, stop);
  if (counts) *counts = totals;
}

}  // namespace vkrt
