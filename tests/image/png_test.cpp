// PNG output: round trip, atomic replacement, and failures that leave nothing behind.
#include <filesystem>

#include <gtest/gtest.h>

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
