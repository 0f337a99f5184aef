// A count with its noun in the right number ("1 batch", "2 batches", "0 lights"), for every
// message that tells the user how many of something there are.
#pragma once

#include <concepts>
#include <string>
#include <string_view>

namespace vkrt {

template <std::integral N>
std::string counted(N n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

}  // namespace vkrt
