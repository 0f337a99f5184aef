// How the commands print the warnings a render reports (RenderRequest::onWarnings and
// onOptionWarning) on stderr: each scene warning as its located diagnostic, each option
// warning as "vkrt: warning: ...". Quiet: none.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/diagnostic.h"

namespace vkrt {

// The scene's warnings (file:line: warning: ...).
std::function<void(const std::vector<Diagnostic>&)> warningPrinter(bool quiet);

// Warnings about options that the scene shows do not apply (--spp for a Whitted scene).
std::function<void(const std::string&)> optionWarningPrinter(bool quiet);

}  // namespace vkrt
