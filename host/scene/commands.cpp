#include "scene/commands.h"

#include "scene/tokenizer.h"

namespace vkrt {
namespace {

template <typename Same>
std::optional<std::size_t> findName(std::span<const std::string_view> names, std::string_view name, Same same) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (same(names[i], name)) return i;
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> indexNamed(std::span<const std::string_view> names, std::string_view name) {
  return findName(names, name, [](std::string_view a, std::string_view b) { return a == b; });
}

std::optional<std::size_t> indexNamedIgnoringCase(std::span<const std::string_view> names, std::string_view name) {
  return findName(names, name, equalIgnoringCase);
}

}  // namespace vkrt
