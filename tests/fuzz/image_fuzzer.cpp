// libFuzzer target for the image readers (PNG, PPM, PFM, OpenEXR, JPEG). Built with
// -DVKRT_FUZZ=ON and clang; run by .ci/fuzz after the parser's (doc/robustness.md, "Fuzzing").
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "fuzz/fuzz_image_input.h"

namespace {

// The file each input is written to, removed when the fuzzer exits.
const std::string& inputPath() {
  static const std::string path = "/tmp/vkrt-image-fuzz-" + std::to_string(::getpid()) + ".img";
  static const bool removedAtExit = std::atexit([] { ::unlink(inputPath().c_str()); }) == 0;
  (void)removedAtExit;
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vkrt::fuzz::oneImageInput(data, size, inputPath());
  return 0;
}
