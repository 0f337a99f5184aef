// FNV-1a and the text of the render identity record.
#include "image/render_identity.h"

#include <cstdio>

namespace vkrt {

void Fnv1a64::add(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash_ ^= p[i];
    hash_ *= 0x100000001b3ULL;   // the FNV prime
  }
}

void Fnv1a64::add(std::string_view bytes) { add(bytes.data(), bytes.size()); }

std::string formatRenderIdentity(std::uint64_t identity) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(identity));
  return text;
}

std::optional<std::uint64_t> parseRenderIdentity(const std::string& value) {
  if (value.size() != 16) return std::nullopt;
  std::uint64_t v = 0;
  for (char c : value) {
    const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (digit < 0) return std::nullopt;
    v = v << 4 | static_cast<std::uint64_t>(digit);
  }
  return v;
}

}  // namespace vkrt
