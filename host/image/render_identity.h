// The identity of a render: a 64-bit FNV-1a hash of the scene file's bytes and of every
// setting that changes the picture, written as the record `vkrt-render` beside a tile's crop
// record and a batch's samples record, so that `vkrt merge` can refuse parts of different
// renders of one size. Knows nothing of rendering: the render layer says what goes in.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "util/hash.h"   // Fnv1a64, which makes the identity

namespace vkrt {

// The keyword of the record (a PNG tEXt chunk, a PPM header comment, a PFM trailer line).
inline constexpr const char* kRenderKeyword = "vkrt-render";

// The record's value: 16 lower-case hex digits.
std::string formatRenderIdentity(std::uint64_t identity);

// The record's value back; nullopt unless it is exactly 16 lower-case hex digits (the one
// spelling of a value, so that records compare as text).
std::optional<std::uint64_t> parseRenderIdentity(const std::string& value);

}  // namespace vkrt
