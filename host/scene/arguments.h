// A command's arguments, read as what the command takes: so many of them, numbers, whole
// numbers in a range, keywords. What cannot be read is an error, what is read otherwise than
// written a warning (an extra argument, a keyword in another case), at the command's line in
// the log; the messages name the command and the argument: "'size' argument 2: expected ...".
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "scene/diagnostic_log.h"
#include "scene/tokenizer.h"

namespace vkrt {

class Arguments {
 public:
  explicit Arguments(DiagnosticLog& log) : log_(log) {}

  // The arguments to read are those of `line`, which outlives their reading.
  void of(const TokenLine& line) { line_ = &line; }

  int count() const { return line_->count - 1; }
  std::string_view operator[](int k) const { return line_->words[k + 1]; }

  // More arguments than `cmd` takes: the first `n` are read, the rest ignored, with a warning.
  void ignoreExtra(std::string_view cmd, int n, const char* usage);

  // Checks the argument count and parses the first `n` arguments as finite numbers.
  bool numbers(std::string_view cmd, int n, const char* usage, double* out);

  // An integer in [lo, hi], given as a number with no fractional part: argument `argIndex`,
  // read as `v`.
  std::optional<long long> integer(std::string_view cmd, double v, int argIndex, const char* what, long long lo,
                                   long long hi);

  // Reads the one argument, a keyword of `names`, into `value` (an enum in the order of
  // `names`). A keyword in another case is read as that keyword, with a warning, as commands are.
  template <typename Enum>
  bool keyword(std::string_view cmd, std::span<const std::string_view> names, Enum& value) {
    std::size_t index = 0;
    if (!keywordIndex(cmd, names, index)) return false;
    value = static_cast<Enum>(index);
    return true;
  }

 private:
  bool keywordIndex(std::string_view cmd, std::span<const std::string_view> names, std::size_t& index);
  void error(std::string message) { log_.error(line_->number, std::move(message)); }

  DiagnosticLog& log_;
  const TokenLine* line_ = nullptr;
};

}  // namespace vkrt
