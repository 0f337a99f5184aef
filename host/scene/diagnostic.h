// Located diagnostics for bad input: FILE:LINE: error: MESSAGE, collected then thrown once.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace vkrt {

struct Diagnostic {
  std::string file;
  int line = 0;
  std::string message;
  // FILE:LINE: error: MESSAGE (or FILE: error: MESSAGE for the file as a whole, line 0).
  std::string format() const {
    return file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": error: " + message;
  }
};

// Every problem found in one scene file. what() lists them all, one per line.
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
