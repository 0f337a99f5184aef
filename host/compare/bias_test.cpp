// The square-by-square bias test of a Monte Carlo image against its reference.
#include "compare/bias_test.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vkrt {

namespace {

constexpr int kFewestPixels = 8;

// One square's sums of the differences (levels of linear light) and of their squares, per
// channel; the sum of the reference's steps; whether the image has a byte of 255.
struct SquareSums {
  int n = 0;
  double sum[3] = {0, 0, 0}, squares[3] = {0, 0, 0}, steps[3] = {0, 0, 0};
  int saturated[3] = {0, 0, 0};   // pixels with a byte of 255 in the channel
  // The sum of squared deviations from the square's own mean (never below 0 by rounding).
  double deviations(int c) const { return std::max(0.0, squares[c] - sum[c] * sum[c] / n); }
};

// How much light a pixel clamped at 255 may have lost, in multiples of 255 levels: a square
// darker than its reference is excused when its clamped pixels could hold what it lacks at
// that much each (a firefly of a few samples), not when one white pixel stands for a square of
// black ones.
constexpr double kClampedExcess = 8.0;

// z of a square's mean difference against its standard error (SquareBias::z), over its `n`
// pixels of which `saturated` are at 255.
double zScore(double mean, double error, double tolerance, int n, int saturated) {
  if (mean < 0 && -mean * n <= kClampedExcess * 255.0 * saturated) return 0;   // clamping darkens noise
  const double beyond = std::fabs(mean) - tolerance;
  if (beyond <= 0) return 0;
  return error > 0 ? beyond / error : std::numeric_limits<double>::infinity();
}

}  // namespace

BiasTest biasTest(const Image& image, const Image& reference, double gamma, double maxZ) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument("biasTest: the images differ in size");
  // Each byte in levels of linear light (and one past 255, for the last byte's step).
  double linear[257];
  for (int b = 0; b <= 256; ++b) linear[b] = 255.0 * std::pow(b / 255.0, gamma);
  const int columns = (image.width + kBiasSquare - 1) / kBiasSquare;
  const int rows = (image.height + kBiasSquare - 1) / kBiasSquare;
  std::vector<SquareSums> grid(static_cast<std::size_t>(columns) * rows);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      SquareSums& s = grid[static_cast<std::size_t>(y / kBiasSquare) * columns + x / kBiasSquare];
      ++s.n;
      const std::uint8_t *a = image.pixel(x, y), *b = reference.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        const double d = linear[a[c]] - linear[b[c]];
        s.sum[c] += d;
        s.squares[c] += d * d;
        s.steps[c] += linear[b[c] + 1] - linear[b[c]];
        s.saturated[c] += a[c] == 255;
      }
    }
  BiasTest t;
  for (int row = 0; row < rows; ++row)
    for (int column = 0; column < columns; ++column) {
      const SquareSums& s = grid[static_cast<std::size_t>(row) * columns + column];
      if (s.n < kFewestPixels) continue;
      const PixelRect square{column * kBiasSquare, row * kBiasSquare,
                             std::min((column + 1) * kBiasSquare, image.width),
                             std::min((row + 1) * kBiasSquare, image.height)};
      ++t.squares;
      for (int c = 0; c < 3; ++c) {
        // The variance: the square's own, or if larger that within the squares around it (3x3,
        // each about its own mean). Monte Carlo noise is skewed: rare bright samples carry much
        // of the mean, and a square that drew none looks both darker and less noisy than it is;
        // its neighbours' spread says what it missed.
        double deviations = 0, freedom = 0;
        for (int r = std::max(0, row - 1); r <= std::min(rows - 1, row + 1); ++r)
          for (int k = std::max(0, column - 1); k <= std::min(columns - 1, column + 1); ++k) {
            const SquareSums& around = grid[static_cast<std::size_t>(r) * columns + k];
            if (around.n < 2) continue;
            deviations += around.deviations(c);
            freedom += around.n - 1;
          }
        const double variance = std::max(s.deviations(c) / (s.n - 1), freedom > 0 ? deviations / freedom : 0.0);
        SquareBias b{square, c, s.sum[c] / s.n, std::sqrt(variance / s.n), 0, s.saturated[c] > 0};
        b.z = zScore(b.mean, b.standardError, kBiasToleranceSteps * s.steps[c] / s.n, s.n, s.saturated[c]);
        if ((t.squares == 1 && c == 0) || b.z > t.worst.z) t.worst = b;
        if (b.z > maxZ) t.over.push_back(b);
      }
    }
  std::stable_sort(t.over.begin(), t.over.end(), [](const SquareBias& a, const SquareBias& b) { return a.z > b.z; });
  return t;
}

}  // namespace vkrt
