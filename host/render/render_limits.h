// Bounds on one render's work, for scene files nobody vouches for (`vkrt grade` renders the
// students' under them). The size, samples and depth are checked once the scene is parsed and
// the command line applied, before anything is built; the time from the start of parsing is
// watched while the render runs (the render's stop hook) and once more at the end. A render
// past a limit ends and throws LimitExceeded, whose message names the limit and the scene.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace vkrt {

struct SceneDesc;

struct RenderLimits {
  double seconds = 0;          // wall-clock seconds, parsing included; 0: none
  std::uint64_t spp = 0;       // a sampled render's samples per pixel; 0: none
  std::uint64_t pixels = 0;    // width x height of the image; 0: none
  int depth = -1;              // `maxdepth` (a path integrator's -1 without Russian roulette exceeds any); -1: none
  bool any() const { return seconds > 0 || spp > 0 || pixels > 0 || depth >= 0; }
};

// Which limit a render went past, and the message that says it ("scene.test: 100000000 samples
// per pixel, past the limit of 4096").
class LimitExceeded : public std::runtime_error {
 public:
  enum class Which { Seconds, Spp, Pixels, Depth };
  LimitExceeded(Which which, const std::string& message) : std::runtime_error(message), which_(which) {}
  Which which() const { return which_; }

 private:
  Which which_;
};

// Throws LimitExceeded when the scene as it will be rendered (its size, its maxdepth, and `spp`
// samples a pixel when `sampled`) is past one of `limits`.
void checkRenderLimits(const RenderLimits& limits, const SceneDesc& scene, bool sampled, std::uint64_t spp);

// The message of a render stopped by its time limit.
LimitExceeded timeLimitExceeded(const RenderLimits& limits, const SceneDesc& scene);

}  // namespace vkrt
