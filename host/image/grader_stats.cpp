// Bias and variance as the CSE 168 grading page reported them (doc/path-tracing.md, "In practice").
#include "image/grader_stats.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace vkrt {
namespace {

// Two passes over d = img - ref: the mean, then the mean square deviation from it.
GraderStats statsOfDifferences(const std::vector<double>& d) {
  GraderStats s;
  if (d.empty()) return s;
  double sum = 0.0;
  for (double x : d) sum += x;
  const double mean = sum / static_cast<double>(d.size());
  double squares = 0.0;
  for (double x : d) squares += (x - mean) * (x - mean);
  s.bias = -mean;   // mean(ref - img)
  s.variance = squares / static_cast<double>(d.size());
  s.rmse = std::sqrt(s.variance + mean * mean);
  return s;
}

void requireSameSize(int w, int h, int refW, int refH) {
  if (w != refW || h != refH)
    throw std::invalid_argument("graderStats: the images differ in size (" + std::to_string(w) + "x" +
                                std::to_string(h) + " against " + std::to_string(refW) + "x" + std::to_string(refH) + ")");
}

}  // namespace

GraderStats graderStats(const Image& image, const Image& reference) {
  requireSameSize(image.width, image.height, reference.width, reference.height);
  std::vector<double> d(image.rgb.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = double(image.rgb[i]) - double(reference.rgb[i]);
  return statsOfDifferences(d);
}

GraderStats graderStats(const RadianceImage& image, const RadianceImage& reference, double gamma) {
  requireSameSize(image.width, image.height, reference.width, reference.height);
  const auto encode = [gamma](float value) {
    const double v = value;
    if (!(v > 0.0)) return 0.0;
    return std::floor(255.0 * std::min(std::pow(v, 1.0 / gamma), 1.0));
  };
  std::vector<double> d(image.rgb.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = encode(image.rgb[i]) - encode(reference.rgb[i]);
  return statsOfDifferences(d);
}

GraderStats graderStatsLinear(const RadianceImage& image, const RadianceImage& reference) {
  requireSameSize(image.width, image.height, reference.width, reference.height);
  std::vector<double> d(image.rgb.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = 255.0 * (double(image.rgb[i]) - double(reference.rgb[i]));
  return statsOfDifferences(d);
}

}  // namespace vkrt
