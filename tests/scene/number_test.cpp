// Number parsing: the fast path must give exactly what the general parser gives.
#include <charconv>
#include <random>

#include <gtest/gtest.h>

#include "scene/number.h"

using namespace vkrt;

namespace {

double general(const std::string& s) {
  double v = 0;
  const char* b = s.data();
  if (*b == '+') ++b;
  std::from_chars(b, s.data() + s.size(), v);
  return v;
}

}  // namespace

TEST(Number, AcceptsTheFormsRealFilesUse) {
  double v;
  for (const char* s : {"1", "+1", "-1", "1.", ".5", "-.5", "+.5", "1e-3", "2.5E+1", "0", "-0", "007", "1e22",
                        "123456789012345", "0.000000000000000000000000001", "1234567890123456789", "1e300"}) {
    ASSERT_EQ(parseNumber(s, v), NumberStatus::Ok) << s;
    EXPECT_EQ(v, general(s)) << s;
  }
}

TEST(Number, RejectsWhatIsNotAFiniteNumber) {
  double v;
  for (const char* s : {"", "+", "-", ".", "e5", "1e", "1e+", "x", "1x", "1.2.3", "--1", "+-1", "1,5", "0x10"})
    EXPECT_EQ(parseNumber(s, v), NumberStatus::NotANumber) << s;
  for (const char* s : {"nan", "inf", "-inf", "infinity", "1e999", "-1e400"})
    EXPECT_EQ(parseNumber(s, v), NumberStatus::NotFinite) << s;
}

TEST(Number, FastPathIsCorrectlyRounded) {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 200000; ++i) {
    std::uint64_t m = rng() % 1000000000000000ull;
    int scale = static_cast<int>(rng() % 40) - 20;
    std::string s = std::to_string(m);
    if (rng() % 2) {
      int point = static_cast<int>(rng() % (s.size() + 1));
      s.insert(static_cast<std::size_t>(point), ".");
    }
    if (rng() % 3 == 0) s += "e" + std::to_string(scale);
    if (rng() % 2) s = "-" + s;
    double v;
    ASSERT_EQ(parseNumber(s, v), NumberStatus::Ok) << s;
    ASSERT_EQ(v, general(s)) << s;
  }
}
