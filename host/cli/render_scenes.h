// Rendering scene files, as the render command asks: one scene (with --check: compared with a
// reference), or several in one process (a batch); and --list-devices. Every command first
// names the files it reads and writes to one RunFiles (cli/run_files.h).
#pragma once

#include "cli/options.h"

namespace vkrt {

// One scene: the scene file and the --check reference are inputs; the heatmap and the image
// (its path known once the scene is parsed, checked before the render starts) outputs. The
// reference is read before anything is rendered. Throws what the render throws.
int renderOne(RenderOptions& options);

// Several scenes in one process, sharing the Vulkan context: one line per scene, then a
// summary; a failed scene does not stop the others, a signal does. Returns the highest of
// the scenes' exit statuses.
int renderBatch(const RenderOptions& o);

// --list-devices: the Vulkan devices, one a line on stdout.
int printDevices();

}  // namespace vkrt
