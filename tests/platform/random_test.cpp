// The platform layer's random bytes (host/platform/random.h): getrandom on Linux,
// BCryptGenRandom on Windows (under Wine). Standard C++, gtest and the layer only.
#include <array>
#include <cstddef>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "platform/random.h"

TEST(RandomBytes, FillEveryByteAndDifferEachTime) {
  std::set<std::vector<unsigned char>> seen;
  std::array<int, 256> counts{};
  for (int i = 0; i < 64; ++i) {
    std::vector<unsigned char> bytes(16, 0);
    vkrt::platform::randomBytes(bytes.data(), bytes.size());
    for (unsigned char b : bytes) ++counts[b];
    seen.insert(bytes);
  }
  EXPECT_EQ(seen.size(), 64u);   // 128 bits each: a repeat would be a broken source
  // 1024 bytes: far more than one value each, were the bytes left as they were (0) or filled
  // with one value.
  int values = 0;
  for (int c : counts) values += c > 0;
  EXPECT_GT(values, 200);
  std::vector<unsigned char> large(1 << 20, 0);   // more than one call of the source may give
  vkrt::platform::randomBytes(large.data(), large.size());
  std::size_t zeros = 0;
  for (std::size_t i = large.size() - 4096; i < large.size(); ++i) zeros += large[i] == 0;
  EXPECT_LT(zeros, 100u) << "the end of a large request was left unfilled";
}
