#include "scene/commands.h"

#include "scene/tokenizer.h"

namespace vkrt {

std::optional<Command> commandNamed(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kCommandNames); ++i)
    if (kCommandNames[i] == name) return static_cast<Command>(i);
  return std::nullopt;
}

std::optional<Command> commandNamedIgnoringCase(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kCommandNames); ++i)
    if (equalIgnoringCase(kCommandNames[i], name)) return static_cast<Command>(i);
  return std::nullopt;
}

}  // namespace vkrt
