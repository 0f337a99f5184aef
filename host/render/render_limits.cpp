// The checks of render_limits.h, and their messages.
#include "render/render_limits.h"

#include <cstdio>

#include "scene/integrator_table.h"
#include "scene/scene_desc.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

}  // namespace

void checkRenderLimits(const RenderLimits& limits, const SceneDesc& scene, bool sampled, std::uint64_t spp) {
  const std::string file = abbreviated(scene.sourcePath);
  const std::uint64_t pixels = static_cast<std::uint64_t>(scene.width) * static_cast<std::uint64_t>(scene.height);
  if (limits.pixels > 0 && pixels > limits.pixels)
    throw LimitExceeded(LimitExceeded::Which::Pixels,
                        file + ": a " + std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image (" +
                            std::to_string(pixels) + " pixels) is past the limit of " +
                            std::to_string(limits.pixels) + " pixels");
  if (limits.depth >= 0) {
    const bool path = scene.path.integrator != Integrator::Raytracer;
    if (scene.maxDepth < 0 && path && !scene.path.russianRoulette)
      throw LimitExceeded(LimitExceeded::Which::Depth,
                          file + ": 'maxdepth -1' with 'russianroulette off' has no depth limit, and the limit is " +
                              std::to_string(limits.depth));
    if (scene.maxDepth > limits.depth)
      throw LimitExceeded(LimitExceeded::Which::Depth, file + ": maxdepth " + std::to_string(scene.maxDepth) +
                                                           " is past the limit of " + std::to_string(limits.depth));
  }
  if (limits.spp > 0 && sampled && (spp == 0 || spp > limits.spp))
    throw LimitExceeded(LimitExceeded::Which::Spp,
                        file + ": " + (spp == 0 ? std::string("unbounded") : std::to_string(spp)) +
                            " samples per pixel, past the limit of " + std::to_string(limits.spp));
}

LimitExceeded timeLimitExceeded(const RenderLimits& limits, const SceneDesc& scene) {
  return LimitExceeded(LimitExceeded::Which::Seconds, abbreviated(scene.sourcePath) + ": not rendered within the time limit of " +
                                                          seconds(limits.seconds) + " s");
}

}  // namespace vkrt
