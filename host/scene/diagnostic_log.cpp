#include "scene/diagnostic_log.h"

#include <algorithm>
#include <iterator>

namespace vkrt {
namespace {

constexpr const char* kWarningKindNames[] = {
    "unknown commands", "keywords in another case", "extra arguments", "repeated commands",
    "commands before 'size'", "output names", "commands the integrator does not use", "paths without an end",
    "values clamped",
    "scenes without lights", "line ends", "coordinates beyond the exact range"};
static_assert(std::size(kWarningKindNames) == static_cast<std::size_t>(WarningKind::Count));

}  // namespace

void DiagnosticLog::error(int line, std::string message) {
  if (full()) return;
  diagnostics_.push_back({file_, line, std::move(message), Severity::Error});
  if (++errorCount_ == kMaxErrors)
    diagnostics_.push_back({file_, line, "too many errors; stopping here", Severity::Error});
}

void DiagnosticLog::warn(int line, WarningKind kind, std::string message) {
  const auto k = static_cast<std::size_t>(kind);
  if (++warnings_[k] > kMaxWarningsPerKind) {
    if (suppressedFrom_[k] == 0) suppressedFrom_[k] = line;
    suppressedTo_[k] = line;
    return;
  }
  if (strict_) return error(line, std::move(message) + " [--strict]");
  diagnostics_.push_back({file_, line, std::move(message), Severity::Warning});
}

void DiagnosticLog::onlyError(int line, std::string message) {
  diagnostics_.clear();
  errorCount_ = 0;
  error(line, std::move(message));
  onlyError_ = true;
}

// "... and N more of this kind", one per kind that went over the limit, at the first line
// not listed.
void DiagnosticLog::summarise() {
  for (std::size_t k = 0; k < kKinds; ++k) {
    if (warnings_[k] <= kMaxWarningsPerKind) continue;
    const int more = warnings_[k] - kMaxWarningsPerKind;
    std::string lines = more == 1 ? "on line " + std::to_string(suppressedFrom_[k])
                                  : "on lines " + std::to_string(suppressedFrom_[k]) + " to " +
                                        std::to_string(suppressedTo_[k]);
    diagnostics_.push_back({file_, suppressedFrom_[k],
                            "... and " + std::to_string(more) + " more of this kind (" + kWarningKindNames[k] +
                                "), " + lines + (strict_ ? " [--strict]" : ""),
                            strict_ ? Severity::Error : Severity::Warning});
    if (strict_) ++errorCount_;
  }
}

std::vector<Diagnostic> DiagnosticLog::close() {
  if (!onlyError_) summarise();
  std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
  if (errorCount_ > 0) throw SceneError(std::move(diagnostics_));
  return std::move(diagnostics_);
}

}  // namespace vkrt
