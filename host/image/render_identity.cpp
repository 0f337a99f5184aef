// The text of the render identity record.
#include "image/render_identity.h"

#include <cstdio>

namespace vkrt {

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
