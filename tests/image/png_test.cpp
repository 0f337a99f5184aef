// PNG output: round trip, each row's filter (the cheapest, as the specification computes it),
// atomic replacement, and failures that leave nothing behind.
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

#include "image/png.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

TEST(Png, RoundTripIsExact) {
  std::string dir = freshDir("png/roundtrip");
  Image img = gradient(37, 21);
  writePngAtomic(img, dir + "/a.png");
  Image back = readImage(dir + "/a.png");
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 21);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_EQ(fileCount(dir), 1u);   // no temporary file left
}

namespace {

// The PNG specification's predictors (section 9.2), written from its text, byte by byte.
int predictPng(int type, int a, int b, int c) {
  switch (type) {
    case 0: return 0;
    case 1: return a;
    case 2: return b;
    case 3: return (a + b) / 2;
    case 4: {
      int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
      if (pa <= pb && pa <= pc) return a;
      return pb <= pc ? b : c;
    }
  }
  ADD_FAILURE() << "no PNG filter type " << type;
  return 0;
}

// The specification's prediction of byte i of `row` by filter `type`, from the byte a pixel
// to the left (a), the one above (b) and the one above-left (c); 0 outside the image (`above`
// null for the first row).
int predictAt(int type, const std::uint8_t* row, const std::uint8_t* above, std::size_t i) {
  const int a = i >= 3 ? row[i - 3] : 0, b = above ? above[i] : 0, c = above && i >= 3 ? above[i - 3] : 0;
  return predictPng(type, a, b, c);
}

// The IDAT stream of a PNG file, inflated: for each row, its filter type and filtered bytes.
std::vector<std::uint8_t> inflatedImageData(const std::string& path, std::size_t expected) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::uint8_t> deflated;
  for (std::size_t at = 8; at + 12 <= file.size();) {
    std::size_t length = std::size_t{file[at]} << 24 | std::size_t{file[at + 1]} << 16 |
                         std::size_t{file[at + 2]} << 8 | file[at + 3];
    if (at + 12 + length > file.size()) {
      ADD_FAILURE() << path << ": a chunk runs past the end of the file";
      break;
    }
    if (std::string(file.begin() + at + 4, file.begin() + at + 8) == "IDAT")
      deflated.insert(deflated.end(), file.begin() + at + 8, file.begin() + at + 8 + length);
    at += 12 + length;
  }
  std::vector<std::uint8_t> out(expected);
  uLongf size = expected;
  EXPECT_EQ(uncompress(out.data(), &size, deflated.data(), deflated.size()), Z_OK);
  EXPECT_EQ(size, expected);
  return out;
}

}  // namespace

// Each row takes the filter whose output has the least sum of magnitudes (the first such),
// recomputed here from the specification's predictors; rows built so that each predictor is
// exact for them, rows of noise, and rows of zeros with a few ones (which filter 0 leaves
// nearly zero) make every filter type the choice of some row, and the file decodes
// (stb_image) to the same pixels.
TEST(Png, EachRowTakesTheCheapestFilter) {
  const int w = 53, h = 60;
  Image img(w, h);
  std::mt19937 random(7);
  auto byte = [&] { return static_cast<int>(random() & 255u); };
  for (int y = 0; y < h; ++y) {
    std::uint8_t* row = img.pixel(0, y);
    const std::uint8_t* above = y > 0 ? img.pixel(0, y - 1) : nullptr;
    const int kind = y % 6;   // 0: noise, 1-4: exact for that predictor, 5: zeros with a few ones
    for (std::size_t i = 0; i < std::size_t{w} * 3; ++i) {
      if (kind == 0 || (i < 3 && kind != 5)) row[i] = static_cast<std::uint8_t>(byte());
      else if (kind == 5) row[i] = static_cast<std::uint8_t>(byte() % 9 == 0 ? 1 : 0);
      else row[i] = static_cast<std::uint8_t>(predictAt(kind, row, above, i) + (byte() % 7 == 0 ? 1 : 0));
    }
  }
  std::string dir = freshDir("png/filters");
  writePngAtomic(img, dir + "/a.png");
  EXPECT_EQ(readImage(dir + "/a.png").rgb, img.rgb);

  const std::size_t rowBytes = std::size_t{w} * 3;
  std::vector<std::uint8_t> data = inflatedImageData(dir + "/a.png", (rowBytes + 1) * h);
  std::set<int> chosen;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = img.pixel(0, y);
    const std::uint8_t* above = y > 0 ? img.pixel(0, y - 1) : nullptr;
    std::array<long, 5> cost{};
    for (int type = 0; type < 5; ++type)
      for (std::size_t i = 0; i < rowBytes; ++i) {
        int v = (row[i] - predictAt(type, row, above, i)) & 255;
        cost[type] += v < 128 ? v : 256 - v;
      }
    int cheapest = 0;
    for (int type = 1; type < 5; ++type)
      if (cost[type] < cost[cheapest]) cheapest = type;
    const std::uint8_t* stored = data.data() + y * (rowBytes + 1);
    ASSERT_EQ(stored[0], cheapest) << "row " << y;
    for (std::size_t i = 0; i < rowBytes; ++i)
      ASSERT_EQ(stored[i + 1], (row[i] - predictAt(cheapest, row, above, i)) & 255) << "row " << y << ", byte " << i;
    chosen.insert(cheapest);
  }
  EXPECT_EQ(chosen, (std::set<int>{0, 1, 2, 3, 4}));
}

TEST(Png, ReplacesAnExistingFileWhole) {
  std::string dir = freshDir("png/replace");
  writeFile(dir + "/a.png", "old contents");
  writePngAtomic(gradient(4, 4), dir + "/a.png");
  EXPECT_EQ(readImage(dir + "/a.png").rgb, gradient(4, 4).rgb);
  EXPECT_EQ(fileCount(dir), 1u);
}

TEST(Png, RelativePathWithoutDirectory) {
  std::string dir = freshDir("png/relative");
  auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  writePngAtomic(gradient(2, 2), "plain.png");
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(fileExists(dir + "/plain.png"));
}

TEST(Png, FailuresThrowIoErrorAndLeaveNothing) {
  std::string dir = freshDir("png/fail");
  EXPECT_THROW(writePngAtomic(gradient(2, 2), dir + "/missing/a.png"), IoError);
  EXPECT_THROW(checkOutputWritable(dir + "/missing/a.png"), IoError);
  EXPECT_THROW(checkOutputWritable(dir), IoError);   // a directory
  EXPECT_THROW(checkOutputWritable("/proc/a.png"), IoError);
  EXPECT_NO_THROW(checkOutputWritable(dir + "/fine.png"));
  EXPECT_EQ(fileCount(dir), 0u);   // the writability probe cleaned up after itself
  EXPECT_THROW(readImage(dir + "/none.png"), IoError);
}
