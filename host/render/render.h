// The whole pipeline for one scene file: parse -> flatten -> render (a backend) -> PNG.
// Knows nothing of the command line; main() turns its exceptions into exit codes.
#pragma once

#include <optional>
#include <string>

#include "cpu/reference.h"
#include "render/progress.h"

namespace vkrt {

enum class Backend { Cpu };

struct RenderRequest {
  std::string scenePath;
  std::optional<std::string> output;   // overrides the scene's `output`
  Backend backend = Backend::Cpu;
  int threads = 0;                     // 0: every hardware thread
};

struct RenderReport {
  std::string outputPath;
  int width = 0, height = 0, maxDepth = 0, threads = 0;
  std::size_t triangles = 0, spheres = 0, lights = 0, bvhNodes = 0;
  double parseSeconds = 0, buildSeconds = 0, renderSeconds = 0, writeSeconds = 0;
  RayCounts rays;
};

// Throws SceneError (bad scene, including an unwritable `output`), IoError (files).
RenderReport renderSceneFile(const RenderRequest& request, ProgressBar& progress);

// The output path for a parsed scene, checked before rendering. A bad `output` line in the
// scene is a SceneError at that line; a bad override is an IoError.
std::string resolveOutput(const SceneDesc& scene, const std::optional<std::string>& override);

}  // namespace vkrt
