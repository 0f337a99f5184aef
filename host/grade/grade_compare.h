// One submitted image against its reference: the figures of `vkrt diff` and of the course
// grader, pass or fail under the scene's thresholds, the figure a table shows, and where the
// failing pixels lie. Knows nothing of files or pages.
#pragma once

#include <string>
#include <vector>

#include "grade/grade_thresholds.h"
#include "compare/bias_test.h"
#include "compare/flip.h"
#include "compare/image_diff.h"
#include "image/crop.h"
#include "image/grader_stats.h"

namespace vkrt {

enum class GradeOutcome { Pass, Fail, Missing, Unreadable };
const char* outcomeName(GradeOutcome o);   // "pass", "fail", "missing", "unreadable"

// The one figure an overview shows for a scene, named by its thresholds: the pixels over the
// first --max-pixels-over step, else the largest difference, else the mean FLIP error, else
// the variance, else |bias|, else the largest z of the squares' bias; with no threshold, the
// pixels that differ at all.
struct KeyFigure {
  std::string label;   // "pixels over 2/255"
  double value = 0;
  std::string text;    // "37 (0.012%)"
};
std::string keyFigureLabel(const GradeThresholds& t);

struct Grade {
  GradeOutcome outcome = GradeOutcome::Missing;
  std::vector<std::string> failures;   // why it failed (or the error for unreadable ones)
  int width = 0, height = 0;           // the submission's
  // The figures of `vkrt diff` (8-bit steps) and of the grader (8-bit units).
  int maxDiff = 0;
  double rmse = 0, psnr = 0;
  long long differing = 0, over1 = 0, over2 = 0;
  GraderStats stats;
  FlipStats flip;   // LDR-FLIP of the two 8-bit images; HDR-FLIP of their linear images when both have one
  BiasTest bias;    // square by square (compare/bias_test.h); its `over` filled under --max-bias-z
  KeyFigure key;
  std::vector<PixelRect> regions;   // boxes around the failing pixels, largest first
  long long moreRegions = 0;        // boxes left out of `regions`
};

// The grade of an image of width x height against a reference of another size: it fails,
// saying both sizes (its pixels need not be read).
Grade sizeDiffers(int width, int height, int referenceWidth, int referenceHeight, const GradeThresholds& t);

// The grade of `submission` against `reference` under `t`; `diff` and `flipMap` (each may be
// null) receive the comparison and FLIP's error map (for the report's images) when the sizes
// agree. A size that differs fails. With both linear images (a float submission, or one
// rendered in the run, against a float reference), FLIP is HDR-FLIP of those; the rest of
// the grade is of the 8-bit images whatever they came from.
Grade gradeImage(const Image& submission, const Image& reference, const GradeThresholds& t, ImageDiff* diff,
                 FlipMap* flipMap = nullptr, const RadianceImage* submissionLinear = nullptr,
                 const RadianceImage* referenceLinear = nullptr);

// The boxes around the pixels of `diff` that differ by more than `steps`: the image cut into
// `cell` x `cell` squares, the squares holding such pixels joined where they touch (sides or
// corners), each group's bounding box; at most `limit`, those with the most pixels first
// (`more` receives how many were left out).
std::vector<PixelRect> failingRegions(const ImageDiff& diff, int steps, int cell, std::size_t limit, long long* more);

// The same of the squares of `bias.over` (an image of `width` x `height`): the biased squares,
// those with the most biased channels first.
std::vector<PixelRect> biasedRegions(const BiasTest& bias, int width, int height, std::size_t limit, long long* more);

}  // namespace vkrt
