// How messages show text they did not write: bytes escaped, tokens and paths cut short,
// tokens quoted; used by every layer's messages (the scene's diagnostics, the files' errors,
// the grading inputs).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vkrt {

// `text` with each byte for which `escape` holds written as \xHH, the others as they are.
template <class Escape>
std::string escapedWhere(std::string_view text, Escape escape) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string s;
  s.reserve(text.size());
  for (char ch : text) {
    auto c = static_cast<unsigned char>(ch);
    if (escape(c)) {
      s += "\\x";
      s += kHex[c >> 4];
      s += kHex[c & 15];
    } else {
      s += ch;
    }
  }
  return s;
}

// `text` with every byte outside printable ASCII written as \xHH (a byte-order mark, a
// control character, the bytes of UTF-8), so that a message never carries invisible or
// terminal-controlling bytes.
inline std::string escapedBytes(std::string_view text) {
  return escapedWhere(text, [](unsigned char c) { return c < 0x20 || c >= 0x7F; });
}

// `text` with its control characters (bytes below 0x20, and 0x7F) written as \xHH, and every
// other byte (UTF-8 included) as it is: a name that anyone may choose (a student's file) then
// shows as it reads, and never steers the terminal it is printed on.
inline std::string controlsEscaped(std::string_view text) {
  return escapedWhere(text, [](unsigned char c) { return c < 0x20 || c == 0x7F; });
}

// A token as a message echoes it: escapedBytes() of at most its first kEchoedTokenBytes
// bytes, and for a longer one "... (N bytes)" after them, so that one huge token (a
// megabyte-long word, a long argument) never fills the terminal.
inline constexpr std::size_t kEchoedTokenBytes = 200;
// A path as a message names it: whole up to kEchoedPathBytes (PATH_MAX: any path the
// system takes), else cut there with "... (N bytes)"; its bytes as they are but for control
// characters (controlsEscaped).
inline constexpr std::size_t kEchoedPathBytes = 4096;
inline std::string abbreviated(std::string_view text, std::size_t limit = kEchoedPathBytes) {
  if (text.size() <= limit) return controlsEscaped(text);
  return controlsEscaped(text.substr(0, limit)) + "... (" + std::to_string(text.size()) + " bytes)";
}
inline std::string echoed(std::string_view text) {
  if (text.size() <= kEchoedTokenBytes) return escapedBytes(text);
  return escapedBytes(text.substr(0, kEchoedTokenBytes)) + "... (" + std::to_string(text.size()) + " bytes)";
}

// A token as messages quote it: in quotes, its non-printable bytes escaped, a long one cut
// short (echoed()).
inline std::string quoted(std::string_view token) { return "'" + echoed(token) + "'"; }

}  // namespace vkrt
