#include "scene/commands.h"

#include "scene/tokenizer.h"

namespace vkrt {
namespace {

template <typename Same>
std::optional<Command> findCommand(std::string_view name, Same same) {
  for (std::size_t i = 0; i < std::size(kCommandNames); ++i)
    if (same(kCommandNames[i], name)) return static_cast<Command>(i);
  return std::nullopt;
}

}  // namespace

std::optional<Command> commandNamed(std::string_view name) {
  return findCommand(name, [](std::string_view a, std::string_view b) { return a == b; });
}

std::optional<Command> commandNamedIgnoringCase(std::string_view name) {
  return findCommand(name, equalIgnoringCase);
}

}  // namespace vkrt
