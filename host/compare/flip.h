// FLIP, the perceptual difference of two images (Andersson et al., "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020; HDR-FLIP: "Visualizing Errors in Rendered High
// Dynamic Range Images", Eurographics 2021): the error map, its pooled figures and its magma
// picture. Depends on image/ only; knows nothing of files or the command line.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// The viewing condition of FLIP's papers and tools: a 3840-pixel-wide monitor 0.7 m wide seen
// from 0.7 m, about 67.02 pixels per degree of visual angle.
double flipPixelsPerDegree(double distanceMeters, double widthPixels, double widthMeters);
inline const double kFlipDefaultPixelsPerDegree = flipPixelsPerDegree(0.7, 3840.0, 0.7);

// Per-pixel FLIP error in [0, 1], row-major.
struct FlipMap {
  int width = 0, height = 0;
  std::vector<float> error;
};

// LDR-FLIP of two 8-bit images read as sRGB (as PNGs are). FLIP's pipeline is symmetric in its
// two inputs for LDR images; `reference` is named for the reader. Throws std::invalid_argument
// when the sizes differ.
FlipMap ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// LDR-FLIP of two linear RGB images with channels in [0, 1] (values outside are clamped),
// width * height * 3 floats each.
FlipMap ldrFlipLinear(const std::vector<float>& testLinear, const std::vector<float>& referenceLinear, int width,
                      int height, double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// The exposures HDR-FLIP compares at: from `start` to `stop` stops, `count` of them evenly
// spaced (the ends included).
struct FlipExposures {
  double start = 0.0, stop = 0.0;
  int count = 0;
};

// HDR-FLIP's exposures for a reference, as the paper chooses them for the ACES tone mapper:
// start where the brightest pixel's luminance maps to 0.85, stop where the median's does;
// count: stop - start rounded up, at least 2. The median is over every pixel; where it is 0
// (more than half the image black), over the pixels of positive luminance, and a reference of
// no positive luminance at all is compared at exposure 0 alone (FLIP's tools leave both cases
// undefined). Non-finite channels count as described for hdrFlip.
FlipExposures hdrFlipExposures(const RadianceImage& reference);

// HDR-FLIP of two linear-float images: each exposure of `exposures` (hdrFlipExposures of the
// reference when count is 0) tone-mapped with ACES (FLIP's fit, pre-exposure cancelled),
// clamped to [0, 1] and compared by LDR-FLIP; the error is each pixel's largest over the
// exposures. A NaN channel counts as 0 and +infinity as 65504 (the largest half float), so
// that a broken pixel is an error where it lies rather than a NaN that spreads. Throws
// std::invalid_argument when the sizes differ.
FlipMap hdrFlip(const RadianceImage& test, const RadianceImage& reference, FlipExposures* exposures = nullptr,
                double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// The pooled figures of a map: the mean (FLIP's own figure) and percentiles of the per-pixel
// error, each the nearest-rank percentile (the smallest error that at least p% of the pixels
// do not exceed; unweighted, unlike the FLIP tool's weighted quartiles).
struct FlipStats {
  bool hdr = false;   // HDR-FLIP (then `exposures` says which) or LDR-FLIP
  FlipExposures exposures;
  double pixelsPerDegree = kFlipDefaultPixelsPerDegree;   // the viewing condition it was computed for
  double mean = 0.0, median = 0.0, p95 = 0.0, p99 = 0.0, max = 0.0;
};
FlipStats flipStats(const FlipMap& map);

// The map in FLIP's colour map (magma: black for no error, through purple and orange, to pale
// yellow for 1), as the FLIP tools write it: each error e as magma entry round(255 e).
Image flipMagmaImage(const FlipMap& map);

// One line for reports: "mean 0.0123, median 0.0051, p95 0.0620, p99 0.1334, max 0.7413".
std::string flipStatsText(const FlipStats& s);

}  // namespace vkrt
