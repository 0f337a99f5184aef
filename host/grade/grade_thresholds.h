// What decides pass or fail in `vkrt grade`: the comparison thresholds of `vkrt diff` (pixels
// over a step, the largest difference) and the course grader's measures (bias and variance
// of the difference, image/grader_stats.h), given once on the command line or per scene in a
// file (doc/usage.md, "Grading").
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/image_check.h"

namespace vkrt {

// The bounds on rendering a submitted scene file (cli/grade.cpp makes them the render's
// RenderLimits, render/render_limits.h), each settable on
// the command line and per scene: --limit-time S, --limit-spp N, --limit-pixels N and
// --limit-depth D (0 for none). Unset, the defaults: 40 s (a class of 9 scenes that all run
// into it takes 6 minutes, within Gradescope's default timeout of 10), 16384 samples per
// pixel, the reference's own pixel count (a render of another size fails anyway), maxdepth 100.
struct GradeLimits {
  std::optional<double> seconds;
  std::optional<std::uint64_t> spp, pixels;
  std::optional<int> depth;
};
constexpr double kDefaultLimitSeconds = 40;
constexpr std::uint64_t kDefaultLimitSpp = 16384;
constexpr int kDefaultLimitDepth = 100;

struct GradeThresholds {
  CheckThresholds pixels;              // --max-pixels-over, --max-diff, --max-flip
  std::optional<double> maxBias;       // fails when |bias| exceeds it (8-bit units)
  std::optional<double> maxVariance;   // fails when the variance exceeds it (8-bit units squared)
  // fails when a square's mean difference exceeds this many of its standard errors
  // (compare/bias_test.h): the test of a Monte Carlo image
  std::optional<double> maxBiasZ;
  bool monteCarloDefault = false;   // maxBiasZ is the default of a path-traced scene (text() says so)
  double gamma = 1.0;               // the images' encoding, which maxBiasZ's test decodes (the scene's `gamma`)
  double points = 1.0;              // --points: what passing is worth (Gradescope's max_score); no threshold
  GradeLimits limits;               // --limit-*: for a submitted scene file's render; no threshold
  // None at all: any difference fails, as in `vkrt diff`.
  bool any() const { return pixels.any() || maxBias || maxVariance || maxBiasZ; }
  // The options that give these thresholds ("--max-pixels-over 2:0.1% --max-bias 1"), or
  // "any difference fails".
  std::string text() const;
};

// The thresholds of each scene: a scene's line in the file replaces the command line's.
struct ThresholdTable {
  GradeThresholds all;
  std::map<std::string, GradeThresholds> byScene;   // by sceneKey (grade/grade_inputs.h)
  std::map<std::string, int> lineOf;                // by sceneKey: the line that set it
  const GradeThresholds& forScene(const std::string& key) const;
};

// Applies one threshold or limit option to `t`: `name` ("--max-bias", "--limit-time") and its
// value. Returns false for a name that is neither; throws UsageError for a bad value.
bool applyThresholdOption(const std::string& name, const std::string& value, GradeThresholds& t);

// A thresholds file: one scene per line, its name (in double quotes when it holds a space)
// then its options, '#' to the end of the line a comment:
//     scene7      --max-pixels-over 2:0.1%
//     cornellNEE  --max-bias 0.5 --max-variance 250 --limit-time 120
// A line's thresholds (and --points) replace the command line's; its limits replace only the
// limits it names, and a line of limits alone keeps the command line's thresholds.
// Throws IoError when the file cannot be read, UsageError naming the file and line for a bad
// line, a scene named twice, or a scene that has no reference (`knownKeys`).
ThresholdTable readThresholdFile(const std::string& path, const GradeThresholds& commandLine,
                                 const std::vector<std::string>& knownKeys);

}  // namespace vkrt
