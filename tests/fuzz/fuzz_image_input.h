// What the image-reader fuzzer does with one input, shared by the libFuzzer target
// (tests/fuzz/image_fuzzer.cpp) and the test that replays every input it ever failed on
// (tests/fuzz/image-regressions/, run by fuzz_regression_test.cpp): the bytes written to a
// file and read as vkrt reads any image (PNG, PPM, PFM, OpenEXR, JPEG, told by their first
// bytes), with its records. A reader may refuse the file, but only as an IoError that names
// it and says why ("cannot read image 'F': REASON", REASON not empty), or as OutOfMemory;
// anything else (another exception, a crash, a sanitizer's report) is a finding.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image/image_read.h"
#include "util/errors.h"

namespace vkrt::fuzz {

// Reads `data` as the image file at `path` (written there first). Aborts on a finding.
inline void oneImageInput(const std::uint8_t* data, std::size_t size, const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0 || ::write(fd, data, size) != static_cast<ssize_t>(size) || ::close(fd) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
  try {
    (void)readAnyImage(path);
  } catch (const IoError& e) {
    const std::string message = e.what(), prefix = "cannot read image '" + path + "': ";
    std::size_t reason = message.size() > prefix.size() ? message.size() - prefix.size() : 0;
    if (message.rfind(prefix, 0) != 0 || reason < 3) {
      std::fprintf(stderr, "image fuzzer: a refusal without its reason: '%s'\n", message.c_str());
      std::abort();
    }
  } catch (const OutOfMemory&) {
  }
}

}  // namespace vkrt::fuzz
