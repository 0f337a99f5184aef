// The diagnostic log: the located warnings and errors (diagnostic.h) that parsing a scene
// file collects, in the order found, and at the end the file's verdict: its warnings, or one
// SceneError with all of them (doc/scene-format.md, "Warnings and errors").
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "scene/diagnostic.h"

namespace vkrt {

// The kinds of warning (doc/scene-format.md, "Warnings"); each kind is summarised after
// kMaxWarningsPerKind.
enum class WarningKind {
  UnknownCommand, KeywordCase, ExtraArguments, Repeated, BeforeSize, OutputName, NotForIntegrator, EndlessPaths,
  Clamped,
  NoLights,
  LineEnds,
  Magnitude,
  Count
};

class DiagnosticLog {
 public:
  // `file` names the scene in every diagnostic; with `strict` every warning is an error.
  DiagnosticLog(std::string file, bool strict) : file_(std::move(file)), strict_(strict) {}

  // After kMaxErrors errors the log takes no more, and parsing stops.
  bool full() const { return errorCount_ >= kMaxErrors; }

  void error(int line, std::string message);

  // A warning (with --strict, an error). After kMaxWarningsPerKind of its kind, only counted.
  void warn(int line, WarningKind kind, std::string message);

  // A binary file would give an error per line: what was found so far is dropped and the
  // file's one diagnostic is this error (it is not text, and where).
  void onlyError(int line, std::string message);

  // The end: a summary of each kind past kMaxWarningsPerKind, then every diagnostic in line
  // order (the deferred ones, found at the end of file, go to their lines). Throws SceneError
  // with them all when there is an error; else returns the warnings.
  std::vector<Diagnostic> close();

 private:
  static constexpr int kMaxErrors = 50;
  static constexpr std::size_t kKinds = static_cast<std::size_t>(WarningKind::Count);

  void summarise();

  std::string file_;
  bool strict_;
  std::vector<Diagnostic> diagnostics_;   // errors and warnings, as found
  int errorCount_ = 0;
  bool onlyError_ = false;
  std::array<int, kKinds> warnings_{}, suppressedFrom_{}, suppressedTo_{};   // per WarningKind
};

}  // namespace vkrt
