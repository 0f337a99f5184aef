// The measures of the CSE 168 grader (doc/path-tracing.md, "In practice"): bias and variance of an
// image against a reference, over all pixels and channels, in 8-bit units. Knows nothing of
// rendering.
#pragma once

#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

struct GraderStats {
  double bias = 0.0;       // mean(ref - img)
  double variance = 0.0;   // population variance of (img - ref): mean of squares minus square of mean
  double rmse = 0.0;       // sqrt(mean((img - ref)^2)) = sqrt(variance + bias^2)
};

// Over the bytes of two images of one size (throws std::invalid_argument otherwise).
GraderStats graderStats(const Image& image, const Image& reference);

// As the course's grader saw them: both linear images encoded to bytes as the output does,
// byte = floor(255 clamp(L^(1/gamma), 0, 1)) (NaN: 0), then compared as above. This is the
// figure to report beside the course's published ones (bench/convergence computes the same).
GraderStats graderStats(const RadianceImage& image, const RadianceImage& reference, double gamma);

// Over two linear images, each value taken as 255 L (no quantization, no gamma): the same
// measures without the rounding of the bytes.
GraderStats graderStatsLinear(const RadianceImage& image, const RadianceImage& reference);

}  // namespace vkrt
