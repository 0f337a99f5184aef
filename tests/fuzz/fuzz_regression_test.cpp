// Every input that ever crashed the parser fuzzer (tests/fuzz/regressions/) is replayed here,
// plus the project's scenes (the fuzzer's seeds): none may crash or trip a sanitizer.
#include <filesystem>

#include <gtest/gtest.h>

#include "fuzz/fuzz_image_input.h"
#include "fuzz/fuzz_one_input.h"
#include "test_support.h"

using namespace vkrt::test;

TEST(FuzzRegressions, EveryRecordedInputIsHandled) {
  int replayed = 0;
  for (const char* dir : {"tests/fuzz/regressions", "scenes"}) {
    for (const auto& entry : std::filesystem::directory_iterator(sourcePath(dir))) {
      if (!entry.is_regular_file()) continue;
      std::string bytes = readFile(entry.path().string());
      SCOPED_TRACE(entry.path().string());
      vkrt::fuzz::oneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 8);
}

// The image readers' seeds and every input that ever failed their fuzzer
// (tests/fuzz/image-regressions/), read as the fuzzer reads them: each read, or refused with
// its reason (fuzz_image_input.h aborts otherwise).
TEST(FuzzRegressions, EveryRecordedImageInputIsHandled) {
  const std::string path = freshDir("fuzz/image-regressions") + "/input.img";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(sourcePath("tests/fuzz/image-regressions"))) {
    if (!entry.is_regular_file()) continue;
    std::string bytes = readFile(entry.path().string());
    SCOPED_TRACE(entry.path().string());
    vkrt::fuzz::oneImageInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path);
    ++replayed;
  }
  EXPECT_GE(replayed, 1);
}
