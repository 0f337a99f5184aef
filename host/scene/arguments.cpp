#include "scene/arguments.h"

#include <cmath>

#include "util/counted.h"
#include "scene/number.h"

namespace vkrt {

void Arguments::ignoreExtra(std::string_view cmd, int n, const char* usage) {
  if (count() <= n) return;
  const int extra = count() - n;
  std::string takes = n == 0 ? "takes no arguments"
                             : "takes " + counted(n, "argument", "arguments") + " (" + usage + ")";
  std::string ignored = extra == 1 ? std::string("the extra one is ignored")
                                   : "the extra " + std::to_string(extra) + " are ignored";
  log_.warn(line_->number, WarningKind::ExtraArguments,
            "'" + std::string(cmd) + "' " + takes + ", got " + std::to_string(count()) + ": " + ignored);
}

bool Arguments::numbers(std::string_view cmd, int n, const char* usage, double* out) {
  if (count() < n) {
    error("'" + std::string(cmd) + "' expects " + counted(n, "argument", "arguments") + " (" + usage + "), got " +
          std::to_string(count()));
    return false;
  }
  ignoreExtra(cmd, n, usage);
  const Arguments& args = *this;
  bool ok = true;
  for (int k = 0; k < n; ++k) {
    switch (parseNumber(args[k], out[k])) {
      case NumberStatus::Ok: break;
      case NumberStatus::NotANumber:
        error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) + ": expected a number, got " +
              quoted(args[k]));
        ok = false;
        break;
      case NumberStatus::NotFinite:
        error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) + ": expected a finite number, got " +
              quoted(args[k]));
        ok = false;
        break;
      case NumberStatus::TooSmall:
        error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) + ": " + quoted(args[k]) +
              " is too small: below 4.9e-324, the smallest positive double, it would be 0 (write 0)");
        ok = false;
        break;
    }
  }
  return ok;
}

std::optional<long long> Arguments::integer(std::string_view cmd, double v, int argIndex, const char* what,
                                            long long lo, long long hi) {
  if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
    error("'" + std::string(cmd) + "' argument " + std::to_string(argIndex + 1) + ": expected " + what + ", got " +
          quoted((*this)[argIndex]));
    return std::nullopt;
  }
  return static_cast<long long>(v);
}

bool Arguments::keywordIndex(std::string_view cmd, std::span<const std::string_view> names, std::size_t& index) {
  const std::size_t n = names.size();
  std::string usage;
  for (std::size_t i = 0; i < n; ++i) usage += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(names[i]);
  const std::string name(cmd);
  if (count() < 1) {
    error("'" + name + "' expects 1 argument (" + usage + "), got 0");
    return false;
  }
  ignoreExtra(name, 1, usage.c_str());
  const std::string_view word = (*this)[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (names[i] == word) {
      index = i;
      return true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (equalIgnoringCase(names[i], word)) {
      log_.warn(line_->number, WarningKind::KeywordCase,
                quoted(word) + " read as '" + std::string(names[i]) + "' (keywords are case-sensitive)");
      index = i;
      return true;
    }
  }
  error("'" + name + "' argument 1: expected " + usage + ", got " + quoted(word));
  return false;
}

}  // namespace vkrt
