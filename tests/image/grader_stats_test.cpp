// The course grader's measures (doc/path-tracing.md, "In practice") on images whose answer is known.
#include <cmath>

#include <gtest/gtest.h>

#include "image/grader_stats.h"

namespace vkrt {
namespace {

TEST(GraderStats, BiasAndVarianceInBytes) {
  Image ref(2, 1), img(2, 1);
  // Differences img - ref: +2, -2, +4, 0, 0, 2 -> mean 1, so bias = -1; variance =
  // mean((d - 1)^2) = (1 + 9 + 9 + 1 + 1 + 1) / 6 = 22 / 6.
  const int refBytes[6] = {10, 20, 30, 40, 50, 60}, d[6] = {2, -2, 4, 0, 0, 2};
  for (int i = 0; i < 6; ++i) {
    ref.rgb[i] = static_cast<std::uint8_t>(refBytes[i]);
    img.rgb[i] = static_cast<std::uint8_t>(refBytes[i] + d[i]);
  }
  const GraderStats s = graderStats(img, ref);
  EXPECT_DOUBLE_EQ(s.bias, -1.0);
  EXPECT_DOUBLE_EQ(s.variance, 22.0 / 6.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(22.0 / 6.0 + 1.0));
  EXPECT_DOUBLE_EQ(graderStats(ref, ref).variance, 0.0);
}

TEST(GraderStats, LinearImagesInEightBitUnits) {
  RadianceImage ref(1, 1), img(1, 1);
  ref.rgb = {0.5f, 0.5f, 0.5f};
  img.rgb = {0.5f + 1.0f / 255, 0.5f - 1.0f / 255, 0.5f};
  const GraderStats s = graderStatsLinear(img, ref);
  EXPECT_NEAR(s.bias, 0.0, 1e-5);
  EXPECT_NEAR(s.variance, 2.0 / 3.0, 1e-4);   // differences +1, -1, 0 steps
  EXPECT_THROW(graderStatsLinear(RadianceImage(2, 1), ref), std::invalid_argument);
}

TEST(GraderStats, EncodedWithGammaAsTheGraderSawThem) {
  // gamma 2: bytes floor(255 sqrt(L)). ref 0.25 -> 127; img 0.36 -> 153, NaN -> 0, 4.0 -> 255
  // (clamped) against ref 1.0 -> 255. Differences 26, -127, 0: mean -101/3.
  RadianceImage ref(1, 1), img(1, 1);
  ref.rgb = {0.25f, 0.25f, 1.0f};
  img.rgb = {0.36f, std::nanf(""), 4.0f};
  const GraderStats s = graderStats(img, ref, 2.0);
  const double mean = (26.0 - 127.0) / 3.0;
  EXPECT_DOUBLE_EQ(s.bias, -mean);
  EXPECT_NEAR(s.variance, ((26 - mean) * (26 - mean) + (-127 - mean) * (-127 - mean) + mean * mean) / 3.0, 1e-9);
  EXPECT_THROW(graderStats(RadianceImage(2, 1), ref, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace vkrt
