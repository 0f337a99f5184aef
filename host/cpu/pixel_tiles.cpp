#include "cpu/pixel_tiles.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

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
  std::atomic<int> nextTile{0};
  std::mutex mutex;   // guards done, the progress callback and the totals
  std::uint64_t done = 0;
  RayCounts totals;

  auto worker = [&] {
    RayCounts local;
    for (int tile; (tile = nextTile.fetch_add(1)) < tileCount;) {
      if (stop && stop()) break;
      // (x, y): the full image's pixel; its place in `image` is relative to the region.
      int x0 = region.x0 + (tile % tilesX) * kTile, y0 = region.y0 + (tile / tilesX) * kTile;
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
    }
    std::lock_guard lock(mutex);
    totals.primary += local.primary;
    totals.shadow += local.shadow;
    totals.secondary += local.secondary;
    totals.nonFinite += local.nonFinite;
  };

  threads = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, tileCount));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (counts) *counts = totals;
}

}  // namespace vkrt
