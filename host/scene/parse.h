// Scene file parser: .test text -> SceneDesc. The transform stack, the current material and
// the vertex lists live only inside the parser. Knows nothing of Vulkan or rendering.
#pragma once

#include <string>
#include <string_view>

#include "scene/diagnostic.h"
#include "scene/scene_desc.h"

namespace vkrt {

// Largest image edge we accept, in pixels (and so the largest image: 16384 x 16384).
inline constexpr int kMaxImageEdge = 16384;

// Parses scene text. `fileName` is used in diagnostics only. Throws SceneError holding
// every problem found (it reads on after each one).
SceneDesc parseScene(std::string_view text, const std::string& fileName);

// Reads and parses a file. An unreadable file is a SceneError at line 0.
SceneDesc parseSceneFile(const std::string& path);

}  // namespace vkrt
