// 64-bit FNV-1a.
#include "util/hash.h"

namespace vkrt {

void Fnv1a64::add(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash_ ^= p[i];
    hash_ *= 0x100000001b3ULL;   // the FNV prime
  }
}

void Fnv1a64::add(std::string_view bytes) { add(bytes.data(), bytes.size()); }

}  // namespace vkrt
