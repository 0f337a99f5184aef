// vkrt --compare SCENE: render with both backends, nothing written; the total time of each
// and their difference (stdout), each one's breakdown (stderr) only with --stats.
#pragma once

#include "cli/options.h"

namespace vkrt {

// Exit 5 (kExitDiffers) when a threshold is exceeded. Throws what a render throws.
int compareBackends(const RenderOptions& o);

}  // namespace vkrt
