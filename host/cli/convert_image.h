// vkrt convert IN OUT: the image IN written in the format of OUT's name. IN is an input, never
// written; OUT is written whole or not at all.
#pragma once

#include "cli/options.h"

namespace vkrt {

// Throws IoError, UsageError.
int convertImage(const ConvertOptions& options);

}  // namespace vkrt
