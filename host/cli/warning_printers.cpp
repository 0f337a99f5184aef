// How the commands print a render's warnings: warning_printers.h.
#include "cli/warning_printers.h"

#include <cstdio>

namespace vkrt {

std::function<void(const std::vector<Diagnostic>&)> warningPrinter(bool quiet) {
  if (quiet) return nullptr;
  return [](const std::vector<Diagnostic>& warnings) {
    for (const Diagnostic& w : warnings) std::fprintf(stderr, "%s\n", w.format().c_str());
  };
}

std::function<void(const std::string&)> optionWarningPrinter(bool quiet) {
  if (quiet) return nullptr;
  return [](const std::string& w) { std::fprintf(stderr, "vkrt: warning: %s\n", w.c_str()); };
}

}  // namespace vkrt
