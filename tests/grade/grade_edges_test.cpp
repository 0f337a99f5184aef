// The grader's thresholds at their edges: a figure equal to its threshold passes ("exceeds"
// fails, as --help and doc/usage.md say), the next value above it fails; for the bias in
// either direction.
#include <gtest/gtest.h>

#include "grade/grade_compare.h"

using namespace vkrt;

namespace {

// A 4x4 reference of 100s, and a submission of 100 + bias +- spread alternately: its bias
// (mean(ref - img)) is -bias and its variance spread^2, exactly.
void pair(int bias, int spread, Image& submission, Image& reference) {
  reference = Image(4, 4);
  submission = Image(4, 4);
  for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
    reference.rgb[i] = 100;
    submission.rgb[i] = static_cast<std::uint8_t>(100 + bias + (i % 2 ? spread : -spread));
  }
}

GradeOutcome outcome(const Image& img, const Image& ref, std::optional<double> maxBias,
                     std::optional<double> maxVariance) {
  GradeThresholds t;
  t.maxBias = maxBias;
  t.maxVariance = maxVariance;
  return gradeImage(img, ref, t, nullptr).outcome;
}

TEST(GradeEdges, AVarianceEqualToItsThresholdPasses) {
  Image img, ref;
  pair(0, 4, img, ref);   // variance 16
  EXPECT_EQ(outcome(img, ref, std::nullopt, 16.0), GradeOutcome::Pass);
  EXPECT_EQ(outcome(img, ref, std::nullopt, 15.999), GradeOutcome::Fail);
  pair(0, 0, img, ref);   // identical: variance 0 passes --max-variance 0
  EXPECT_EQ(outcome(img, ref, std::nullopt, 0.0), GradeOutcome::Pass);
}

TEST(GradeEdges, ABiasEqualToItsThresholdPassesEitherWay) {
  for (int bias : {3, -3}) {
    Image img, ref;
    pair(bias, 2, img, ref);
    EXPECT_EQ(outcome(img, ref, 3.0, std::nullopt), GradeOutcome::Pass) << bias;
    EXPECT_EQ(outcome(img, ref, 2.999, std::nullopt), GradeOutcome::Fail) << bias;
  }
}

}  // namespace
