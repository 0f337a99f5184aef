// The square-by-square bias test of `vkrt grade --max-bias-z` (compare/bias_test.h), on
// images made here the way a Monte Carlo renderer makes them: each pixel the mean of N
// samples of a skewed distribution (exponential: most samples dim, a few bright) whose mean is
// the reference's radiance, then clamped and encoded to bytes as vkrt's output is
// (floor(255 L^(1/gamma))). Correct images must pass at every sample count, biased ones fail.
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "compare/bias_test.h"

using namespace vkrt;

namespace {

constexpr int kSize = 160;

// The expected radiance at a pixel: a gradient across the image, a dark band, and a bright
// corner past 1 (which the bytes clamp) where a light would be.
double radiance(int x, int y, int c) {
  double v = 0.15 + 0.55 * x / kSize + 0.1 * c;
  if (y > 60 && y < 90) v *= 0.1;
  if (x < 40 && y < 40) v = 1.3;
  return v;
}

std::uint8_t encode(double l, double gamma) {
  const double clamped = std::min(std::max(l, 0.0), 1.0);
  return static_cast<std::uint8_t>(std::floor(255.0 * std::pow(clamped, 1.0 / gamma)));
}

Image reference(double gamma) {
  Image img(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) img.pixel(x, y)[c] = encode(radiance(x, y, c), gamma);
  return img;
}

// A render of `samples` samples a pixel, each the radiance times an exponential variate
// (mean 1), times `scale` (1: correct; 0.95: a light 5% too dim) inside `biased` (everywhere
// when it is empty).
Image render(int samples, double gamma, unsigned seed, double scale = 1.0, PixelRect biased = {}) {
  std::mt19937 rng(seed);
  std::exponential_distribution<double> sample(1.0);
  Image img(kSize, kSize);
  const bool everywhere = biased.width() == 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double sum = 0;
      for (int s = 0; s < samples; ++s) sum += sample(rng);   // one path's weight, all channels
      const bool inside = everywhere || (x >= biased.x0 && x < biased.x1 && y >= biased.y0 && y < biased.y1);
      for (int c = 0; c < 3; ++c)
        img.pixel(x, y)[c] = encode(radiance(x, y, c) * sum / samples * (inside ? scale : 1.0), gamma);
    }
  return img;
}

}  // namespace

TEST(SquareBias, CorrectImagesPassAtEverySampleCountAndGamma) {
  // Tolerance: the default cut-off, z 6. Without the decoding to linear light, gamma 2.2 at one
  // sample fails (the curve bends noise into darkness); without the rule for clamped squares,
  // the bright corner fails.
  for (double gamma : {1.0, 2.2})
    for (int samples : {1, 4, 16, 64})
      for (unsigned seed : {1u, 2u, 3u}) {
        const BiasTest t = biasTest(render(samples, gamma, seed), reference(gamma), gamma);
        EXPECT_LE(t.worst.z, kDefaultMaxBiasZ) << "gamma " << gamma << ", " << samples << " samples, seed " << seed
                                                << ": square (" << t.worst.square.x0 << "," << t.worst.square.y0
                                                << ") channel " << t.worst.channel << " mean " << t.worst.mean;
        EXPECT_TRUE(t.over.empty());
        EXPECT_EQ(t.squares, 100);
      }
}

TEST(SquareBias, ALightTooDimFails) {
  // 10% from 16 samples a pixel, 5% from 64 (at 16, this noise hides 5% within 6 errors).
  for (double gamma : {1.0, 2.2})
    for (int samples : {16, 64, 256}) {
      const BiasTest t = biasTest(render(samples, gamma, 5, samples < 64 ? 0.9 : 0.95), reference(gamma), gamma);
      EXPECT_GT(t.worst.z, kDefaultMaxBiasZ) << "gamma " << gamma << ", " << samples << " samples";
      EXPECT_LT(t.worst.mean, 0);
      EXPECT_FALSE(t.over.empty());
    }
}

TEST(SquareBias, ALocalBiasIsFoundWhereItIs) {
  // 15% too bright in one 32x32 region of a 16-sample render: the squares over the cut-off lie in it.
  const PixelRect region{96, 112, 128, 144};
  const BiasTest t = biasTest(render(16, 1.0, 9, 1.15, region), reference(1.0), 1.0);
  ASSERT_FALSE(t.over.empty());
  for (const SquareBias& s : t.over) {
    EXPECT_GE(s.square.x0, region.x0);
    EXPECT_LE(s.square.x1, region.x1);
    EXPECT_GE(s.square.y0, region.y0);
    EXPECT_LE(s.square.y1, region.y1);
    EXPECT_GT(s.mean, 0);
  }
  EXPECT_GT(t.worst.z, kDefaultMaxBiasZ);
}

TEST(SquareBias, ClampingExcusesOnlyDarkness) {
  // A flat square of 255 in the reference: a noisy image darker there is what clamping does;
  // one brighter where the reference is not clamped is bias whatever the image's 255s.
  Image ref(16, 16), dark(16, 16), bright(16, 16);
  for (int i = 0; i < 256; ++i) {
    for (int c = 0; c < 3; ++c) {
      ref.rgb[3 * i + c] = 200;
      dark.rgb[3 * i + c] = static_cast<std::uint8_t>(i % 4 == 0 ? 255 : 120 + i % 7);
      bright.rgb[3 * i + c] = static_cast<std::uint8_t>(i % 4 == 0 ? 255 : 230 + i % 7);
    }
  }
  EXPECT_EQ(biasTest(dark, ref).worst.z, 0.0);
  EXPECT_TRUE(biasTest(dark, ref).worst.saturated);
  EXPECT_GT(biasTest(bright, ref).worst.z, kDefaultMaxBiasZ);
}

// Clamping can hide only so much: a square of black with one white pixel against a grey
// reference of 128 (that pixel would have had to lose 127 times the brightest byte), or with
// one in sixteen against 200 (11.5 times each), is no noisy render whose fireflies were
// clamped, and fails; a square whose clamped pixels could hold what it lacks at a few times
// 255 each, like the one above, is excused.
TEST(SquareBias, ClampingDoesNotExcuseASquareOfBlackWithAWhiteDot) {
  Image ref(16, 16), bright(16, 16), one(16, 16), sixteen(16, 16);
  for (int i = 0; i < 256; ++i)
    for (int c = 0; c < 3; ++c) {
      ref.rgb[3 * i + c] = 128;
      bright.rgb[3 * i + c] = 200;
      one.rgb[3 * i + c] = static_cast<std::uint8_t>(i == 136 ? 255 : 0);
      sixteen.rgb[3 * i + c] = static_cast<std::uint8_t>(i % 16 == 0 ? 255 : 0);
    }
  EXPECT_GT(biasTest(one, ref).worst.z, kDefaultMaxBiasZ);
  EXPECT_GT(biasTest(sixteen, bright).worst.z, kDefaultMaxBiasZ);
  EXPECT_TRUE(biasTest(sixteen, bright).worst.saturated);
}

TEST(SquareBias, RoundingOfAFlatColourIsNoBias) {
  // Half a step of rounding: z 0; a whole step and no noise at all (error 0): infinite.
  Image ref(32, 32), half(32, 32), whole(32, 32);
  for (std::size_t i = 0; i < ref.rgb.size(); ++i) {
    ref.rgb[i] = 100;
    half.rgb[i] = static_cast<std::uint8_t>(i % 2 == 0 ? 100 : 101);   // mean +0.5
    whole.rgb[i] = 101;
  }
  EXPECT_EQ(biasTest(half, ref).worst.z, 0.0);
  EXPECT_TRUE(std::isinf(biasTest(whole, ref).worst.z));
  EXPECT_EQ(biasTest(whole, ref).squares, 4);
  EXPECT_EQ(biasTest(whole, ref, 1.0, 6.0).over.size(), 12u);   // 4 squares x 3 channels
}

TEST(SquareBias, ASquareThatDrewNoBrightSampleIsJudgedByItsNeighboursSpread) {
  // Nine squares of one grey. Around the centre, each square's 256 pixels are 240 a little
  // dark and 16 bright (mean difference 0: correct, skewed noise); the centre drew no bright
  // sample, so it is darker and calm (its own error alone would make z about 70). Its
  // neighbours' spread says what it missed: z under the cut-off. Darker by 20 instead, it fails.
  auto image = [](int centreDarkness) {
    Image img(48, 48);
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x) {
        const bool centre = x >= 16 && x < 32 && y >= 16 && y < 32;
        const int i = (y % 16) * 16 + x % 16;
        const int v = centre ? 100 - centreDarkness + (i % 3) - 1 : (i % 16 == 0 ? 175 : 95);
        for (int c = 0; c < 3; ++c) img.pixel(x, y)[c] = static_cast<std::uint8_t>(v);
      }
    return img;
  };
  Image ref(48, 48);
  std::fill(ref.rgb.begin(), ref.rgb.end(), std::uint8_t{100});
  const BiasTest missed = biasTest(image(5), ref);
  EXPECT_LT(missed.worst.z, kDefaultMaxBiasZ);
  EXPECT_GT(missed.worst.z, 1.0);   // the centre, weighed
  EXPECT_EQ(missed.worst.square.x0, 16);
  EXPECT_GT(biasTest(image(20), ref).worst.z, kDefaultMaxBiasZ);
}

namespace {

// A grey image of 16-pixel squares: each square's 256 pixels 240 a little dark and 16 bright
// (mean difference 0 against a reference of 100: correct, skewed noise), but for the square at
// (calmX, calmY), which drew no bright sample: darker by `darkness`, and calm.
Image skewedSquaresWithACalmOne(int width, int height, int calmX, int calmY, int darkness) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool calm = x >= calmX && x < calmX + 16 && y >= calmY && y < calmY + 16;
      const int i = (y % 16) * 16 + x % 16;
      const int v = calm ? 100 - darkness + (i % 3) - 1 : (i % 16 == 0 ? 175 : 95);
      for (int c = 0; c < 3; ++c) img.pixel(x, y)[c] = static_cast<std::uint8_t>(v);
    }
  return img;
}

Image grey(int width, int height) {
  Image ref(width, height);
  std::fill(ref.rgb.begin(), ref.rgb.end(), std::uint8_t{100});
  return ref;
}

}  // namespace

// The spread a calm square is judged by comes from every side of it: here from the row of
// squares below alone (a grid one square wide, the calm square on top), and from the column to
// its right alone (a grid one square high, the calm square first). Either way the calm square passes, weighed (z over
// 1), and fails darker by 20.
TEST(SquareBias, TheSpreadAroundASquareComesFromBelowAndFromBesideIt) {
  const BiasTest onTop = biasTest(skewedSquaresWithACalmOne(16, 32, 0, 0, 5), grey(16, 32));
  EXPECT_LT(onTop.worst.z, kDefaultMaxBiasZ);
  EXPECT_GT(onTop.worst.z, 1.0);
  EXPECT_EQ(onTop.worst.square.y0, 0);
  EXPECT_GT(biasTest(skewedSquaresWithACalmOne(16, 32, 0, 0, 20), grey(16, 32)).worst.z, kDefaultMaxBiasZ);
  const BiasTest inARow = biasTest(skewedSquaresWithACalmOne(32, 16, 0, 0, 5), grey(32, 16));
  EXPECT_EQ(inARow.squares, 2);
  EXPECT_LT(inARow.worst.z, kDefaultMaxBiasZ);
  EXPECT_GT(inARow.worst.z, 1.0);
  EXPECT_EQ(inARow.worst.square.x0, 0);
  EXPECT_GT(biasTest(skewedSquaresWithACalmOne(32, 16, 0, 0, 20), grey(32, 16)).worst.z, kDefaultMaxBiasZ);
}

TEST(SquareBias, ImagesOfTwoSizesAreRefused) {
  EXPECT_THROW(biasTest(Image(16, 16), Image(16, 17)), std::invalid_argument);
}
