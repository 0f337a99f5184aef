// JSON string literals.
#include "util/json.h"

#include <cstdio>

namespace vkrt {
namespace {

// The length of the well-formed UTF-8 sequence at s[i] (1-4), or 0 where the bytes are not
// one (a stray continuation byte, a sequence cut short, an overlong form, a surrogate, a
// code point beyond U+10FFFF).
std::size_t utf8Length(const std::string& s, std::size_t i) {
  const unsigned char c = static_cast<unsigned char>(s[i]);
  if (c < 0x80) return 1;
  std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? (c <= 0xEF ? 3 : 0) : c >= 0xC2 && c <= 0xDF ? 2 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  const unsigned char d = static_cast<unsigned char>(s[i + 1]);
  if ((c == 0xE0 && d < 0xA0) || (c == 0xED && d > 0x9F) || (c == 0xF0 && d < 0x90) || (c == 0xF4 && d > 0x8F))
    return 0;
  return n;
}

}  // namespace

std::string jsonQuoted(const std::string& s) {
  std::string q = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const std::size_t n = utf8Length(s, i);
    if (n == 0) {   // not UTF-8 (a file name from another system): the replacement character
      q += "\\ufffd";
      ++i;
      continue;
    }
    if (c == '"' || c == '\\') {
      q += '\\';
      q += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else {
      q.append(s, i, n);
    }
    i += n;
  }
  return q + "\"";
}

}  // namespace vkrt
