// What the parser hands a shape's command (shape_list.h, VKRT_SHAPE_COMMANDS): the line's
// arguments and the parser's state a shape takes. Knows nothing of the scene description.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "scene/arguments.h"

namespace vkrt {

// Lives for the one call of the command's reader.
struct ShapeCommand {
  Arguments& args;                           // the command's arguments (their messages name the command)
  std::function<void(std::string)> error;    // an error at the command's line
  const glm::dmat4& worldFromObject;         // the transform current at the command
  // The current material's index. Called once the shape is accepted, and only then: the
  // parser records the material (and its first shaded surface) when it is called.
  std::function<std::uint32_t()> material;
};

}  // namespace vkrt
