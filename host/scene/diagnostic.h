// Located diagnostics for bad input: FILE:LINE: error|warning: MESSAGE. The parser collects
// them; errors are thrown once, at the end, as one SceneError (doc/scene-format.md, "Warnings and errors").
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace vkrt {

// An error: the scene cannot be rendered as its author meant. A warning: it can, and the
// message says how the line was read (skipped, accepted, the last one counts).
enum class Severity { Warning, Error };

struct Diagnostic {
  std::string file;
  int line = 0;   // 0: the file as a whole
  std::string message;
  Severity severity = Severity::Error;

  bool isError() const { return severity == Severity::Error; }
  // FILE:LINE: error: MESSAGE (or FILE: warning: MESSAGE for the file as a whole, line 0).
  std::string format() const {
    return file + (line > 0 ? ":" + std::to_string(line) : std::string()) +
           (isError() ? ": error: " : ": warning: ") + message;
  }
};

// `text` with every byte outside printable ASCII written as \xHH (a byte-order mark, a
// control character, the bytes of UTF-8), so that a message never carries invisible or
// terminal-controlling bytes.
inline std::string escapedBytes(std::string_view text) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string s;
  s.reserve(text.size());
  for (char ch : text) {
    auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7F) {
      s += ch;
    } else {
      s += "\\x";
      s += kHex[c >> 4];
      s += kHex[c & 15];
    }
  }
  return s;
}

// A token as a message echoes it: escapedBytes() of at most its first kEchoedTokenBytes
// bytes, and for a longer one "... (N bytes)" after them, so that one huge token (a
// megabyte-long word, a long argument) never fills the terminal.
inline constexpr std::size_t kEchoedTokenBytes = 200;
// A path as a message names it: whole up to kEchoedPathBytes (PATH_MAX: any path the
// system takes), else cut there with "... (N bytes)"; its bytes as they are.
inline constexpr std::size_t kEchoedPathBytes = 4096;
inline std::string abbreviated(std::string_view text, std::size_t limit = kEchoedPathBytes) {
  if (text.size() <= limit) return std::string(text);
  return std::string(text.substr(0, limit)) + "... (" + std::to_string(text.size()) + " bytes)";
}
inline std::string echoed(std::string_view text) {
  if (text.size() <= kEchoedTokenBytes) return escapedBytes(text);
  return escapedBytes(text.substr(0, kEchoedTokenBytes)) + "... (" + std::to_string(text.size()) + " bytes)";
}

// A token as messages quote it: in quotes, its non-printable bytes escaped, a long one cut
// short (echoed()).
inline std::string quoted(std::string_view token) { return "'" + echoed(token) + "'"; }

// After this many warnings of one kind (unknown commands, repeated commands, ...) the rest
// of that kind are summarised in one more: "... and N more of this kind".
inline constexpr int kMaxWarningsPerKind = 3;

// A scene that cannot be rendered. diagnostics() holds every problem found in the file, in
// line order: at least one error, and the warnings beside them. what() lists them all, one
// per line.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(std::vector<Diagnostic> diagnostics)
      : std::runtime_error(join(diagnostics)), diagnostics_(std::move(diagnostics)) {}
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  static std::string join(const std::vector<Diagnostic>& ds) {
    std::string s;
    for (const auto& d : ds) s += (s.empty() ? "" : "\n") + d.format();
    return s;
  }
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace vkrt
