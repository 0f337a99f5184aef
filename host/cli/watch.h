// vkrt --watch SCENE: render, then render again each time the scene file changes, in one
// process: the Vulkan instance, device and compiled pipelines of the first render serve the
// next (gpu/pipeline_cache.h), so an edit of one number re-renders in the time of the render
// itself. A path-traced scene then refines: further batches of samples (other seeds) are
// averaged into the image, which is rewritten after each, until the file changes again or
// kMaxBatches batches are in. Each render prints one line; a scene with errors prints them and
// waits for the next change; the image is written whole each time (atomic_file). Ends on a
// signal (Ctrl-C: status 130).
#pragma once

#include <cstdint>
#include <string>

#include "cli/options.h"

namespace vkrt {

inline constexpr int kMaxWatchBatches = 64;

// What a watch tells a viewer besides the image (which goes through the request's
// onImageStart and onImageRows): `vkrt view`'s page (cli/web_view.h). Called on the watch's
// thread; each must return soon.
struct WatchStep {
  int round = 0;                  // 1, 2, ...: a render after each change
  int batch = 1, batches = 1;     // a path-traced image's batches so far, of at most kMaxWatchBatches
  std::uint64_t samples = 1;      // per pixel, in the image so far
  double seconds = 0;             // since the round started (the change was seen)
  std::string output;             // the file written
  std::string line;               // what the watch printed about it
};
class WatchListener {
 public:
  virtual ~WatchListener() = default;
  virtual void roundStarted(int round) = 0;
  virtual void warned(const std::string& line) = 0;   // a warning, as printed (file:line: warning: ...)
  virtual void rendered(const WatchStep& step) = 0;   // an image written (the first of a round, or refined)
  // A round that wrote nothing: its error as printed (with the scene's errors at their lines),
  // and the line that says the watch waits.
  virtual void failed(int round, const std::string& message) = 0;
};

// An output named on the command line that cannot be written (a folder that does not exist):
// no edit of the scene fixes it, so it is an error at once. Throws IoError.
void checkWatchOutputs(const RenderOptions& options);

// Returns the exit status of the signal that ended it. Throws UsageError, IoError (the scene's
// folder cannot be watched), and what the first render throws before anything was shown
// (a device that cannot be made is no reason to wait). `listener`, when given, is told each step.
int watchScene(RenderOptions& options, WatchListener* listener = nullptr);

}  // namespace vkrt
