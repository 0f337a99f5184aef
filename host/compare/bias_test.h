// Whether a Monte Carlo image is an unbiased estimate of its reference: the image cut into
// squares, and in each square and channel the mean of (image - reference) weighed against its
// own standard error. A correct render's noise averages out within a square; a biased one
// (a missing bounce, a light too dim, a wrong BRDF) leaves a mean that its noise does not
// explain. Depends on image/ only.
#pragma once

#include <vector>

#include "image/crop.h"
#include "image/image.h"

namespace vkrt {

// Pixels on a side of the squares (the last row and column of squares may be narrower).
inline constexpr int kBiasSquare = 16;
// A square's mean difference within half a byte's step of zero is no bias: the bytes'
// rounding (floor(255 x)) moves a square of one flat colour by up to this much.
inline constexpr double kBiasToleranceSteps = 0.5;
// The default cut-off (`vkrt grade` on path-traced scenes). Were the noise normal, a correct
// square would pass 6 standard errors but for a chance of 2e-9; Monte Carlo noise has heavier
// tails. Measured on cornellNEE at 480x480 against a 1,024-sample reference, 18 correct renders
// of 1 to 64 samples: largest z 4.72; a light 5% too dim: 5.43 at 4 samples, 6.46 at 16,
// 11.7 at 64 (doc/usage.md, "Grading a class").
inline constexpr double kDefaultMaxBiasZ = 6.0;

// One square and channel: the mean of (image - reference) in levels of linear light (a byte b
// is 255 (b / 255)^gamma: the bytes themselves when gamma is 1), its standard error (the
// standard deviation over the root of the pixel count; the deviation the square's own, or
// if larger the pooled one within the 3x3 squares around it), and
// z = (|mean| - tolerance) / error, at least 0 (infinite when the error is 0 and the mean is
// beyond the tolerance), the tolerance being kBiasToleranceSteps of the reference's bytes'
// steps there. Clamping at 255 can only darken a noisy image, so a square darker than its
// reference is z 0 when the image has a byte of 255 in that channel there.
struct SquareBias {
  PixelRect square;
  int channel = 0;   // 0 red, 1 green, 2 blue
  double mean = 0, standardError = 0, z = 0;
  bool saturated = false;   // the image has a byte of 255 in this channel here
};

struct BiasTest {
  SquareBias worst;                   // the square and channel of the largest z
  std::vector<SquareBias> over;       // those over the cut-off given, largest z first
  int squares = 0;                    // squares tested (times 3 channels)
};

// Over two 8-bit images of one size (throws std::invalid_argument otherwise), both encoded with
// `gamma` (byte = floor(255 L^(1/gamma))): decoding to linear light first, so that the
// encoding's curve does not bend noise into bias. `over` lists the squares whose z exceeds
// `maxZ`. Squares of fewer than 8 pixels are left out (their error means little).
BiasTest biasTest(const Image& image, const Image& reference, double gamma = 1.0, double maxZ = kDefaultMaxBiasZ);

}  // namespace vkrt
