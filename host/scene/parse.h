// Scene file parser: .test text -> SceneDesc. The transform stack, the current material and
// the vertex lists live only inside the parser. Knows nothing of Vulkan or rendering.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene/diagnostic.h"
#include "scene/scene_desc.h"

namespace vkrt {

// Largest image edge we accept, in pixels (and so the largest image: 16384 x 16384).
inline constexpr int kMaxImageEdge = 16384;

struct ParseOptions {
  bool strict = false;   // every warning is an error (for graders and CI)
  // The command line names the output file (-o FILE): the scene's `output` line names nothing
  // written, so its name is not checked.
  bool outputOverridden = false;
  // How the `output` line's name is judged, by the layer that knows the image formats
  // (image/image_file.h, outputNameProblem): why vkrt would not write the file its name says,
  // or "" for a good name. Null: names are not judged (the parser knows no image format).
  std::string (*outputNameProblem)(const std::string& name) = nullptr;
};

struct ParsedScene {
  SceneDesc scene;
  // What the file does that the format does not say but vkrt accepts (doc/scene-format.md, "Warnings"),
  // in line order: each says how its line was read. Empty for a clean file.
  std::vector<Diagnostic> warnings;
};

// Parses scene text. `fileName` is used in diagnostics only. Throws SceneError holding every
// diagnostic, warnings included, when there is an error (with `strict`: a warning); it reads
// on after each one.
ParsedScene parseSceneWithWarnings(std::string_view text, const std::string& fileName,
                                   const ParseOptions& options = {});

// Reads and parses a file. Throws IoError when it cannot be opened or read, SceneError for
// a line or a file past the limits of scene_file.h, Interrupted when a signal stops a read (a FIFO).
ParsedScene parseSceneFileWithWarnings(const std::string& path, const ParseOptions& options = {});

// The same, for callers with no use for warnings (tests, tools): the warnings are dropped.
SceneDesc parseScene(std::string_view text, const std::string& fileName);
SceneDesc parseSceneFile(const std::string& path);

}  // namespace vkrt
