// libFuzzer target for the scene parser (and what it lets through). Built with
// -DVKRT_FUZZ=ON and clang; run by .ci/fuzz (doc/robustness.md, "Fuzzing").
#include "fuzz_one_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vkrt::fuzz::oneInput(data, size);
  return 0;
}
