// Located diagnostics for bad input: FILE:LINE: error|warning: MESSAGE. The parser collects
// them; errors are thrown once, at the end, as one SceneError (doc/scene-format.md, "Warnings and errors").
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "util/text.h"   // escapedBytes, echoed, quoted, abbreviated: how messages show text

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
    return abbreviated(file) + (line > 0 ? ":" + std::to_string(line) : std::string()) +
           (isError() ? ": error: " : ": warning: ") + message;
  }
};

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
