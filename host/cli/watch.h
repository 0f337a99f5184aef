// vkrt --watch SCENE: render, then render again each time the scene file changes, in one
// process: the Vulkan instance, device and compiled pipelines of the first render serve the
// next (gpu/pipeline_cache.h), so an edit of one number re-renders in the time of the render
// itself. A path-traced scene then refines: further batches of samples (other seeds) are
// averaged into the image, which is rewritten after each, until the file changes again or
// kMaxBatches batches are in. Each render prints one line; a scene with errors prints them and
// waits for the next change; the image is written whole each time (atomic_file). Ends on a
// signal (Ctrl-C: status 130).
#pragma once

#include "cli/options.h"

namespace vkrt {

inline constexpr int kMaxWatchBatches = 64;

// Returns the exit status of the signal that ended it. Throws UsageError, IoError (the scene's
// folder cannot be watched), and what the first render throws before anything was shown
// (a device that cannot be made is no reason to wait).
int watchScene(RenderOptions& options);

}  // namespace vkrt
