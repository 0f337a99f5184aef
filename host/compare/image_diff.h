// Comparing two 8-bit images: counts of pixels over a threshold, worst pixels, and an
// amplified difference image. Used by the tests (and by the CLI's comparison tools).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace vkrt {

struct PixelDiff {
  int x = 0, y = 0;
  int maxChannelDiff = 0;   // in 8-bit steps
};

struct ImageDiff {
  int width = 0, height = 0;
  long long pixels = 0;
  int maxChannelDiff = 0;
  double meanAbs = 0.0;                 // mean absolute channel difference, in 8-bit steps
  double rmse = 0.0;                    // root mean square channel difference, in 8-bit steps
  std::vector<PixelDiff> differing;     // every pixel with any difference, row-major order

  // Pixels whose largest channel difference exceeds `steps` 8-bit steps.
  long long countOver(int steps) const;
  // The `n` largest differences, as "(x,y) d" text.
  std::string worst(int n) const;
  // Peak signal-to-noise ratio in dB (peak 255); infinity for identical images.
  double psnr() const;
};

// Throws std::invalid_argument when the sizes differ.
ImageDiff compare(const Image& a, const Image& b);

// |a - b| per channel times `gain`, clamped; unchanged pixels are black.
Image amplifiedDifference(const Image& a, const Image& b, int gain);

// A heatmap of each pixel's largest channel difference: black for none, then blue, cyan,
// green, yellow and red at `scaleSteps` 8-bit steps or more; below it, a legend strip with
// the colour ramp and its end values ("1/255" and the scale) written in a small pixel font.
Image differenceHeatmap(const ImageDiff& diff, int scaleSteps);

}  // namespace vkrt
