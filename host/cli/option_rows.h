// Each command's table of options (cli/option_table.h), for --help (cli/usage_text.cpp) and
// the parser (cli/options.cpp), which defines them.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "cli/option_table.h"
#include "cli/options.h"

namespace vkrt {

// The render command's options while they are read (diff reads the same): -o as given, told
// a file or a folder once every scene is known.
struct RenderCommandLine : RenderOptions {
  std::optional<std::string> output;
};

std::span<const OptionRow<RenderCommandLine>> renderOptionRows();   // also diff's
std::span<const OptionRow<MergeOptions>> mergeOptionRows();
std::span<const OptionRow<ConvertOptions>> convertOptionRows();
std::span<const OptionRow<GradeOptions>> gradeOptionRows();

}  // namespace vkrt
