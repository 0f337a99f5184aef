// Reading a scene file: its text, within the limits of a line and of a file, up to the first
// byte that is not text (where the tokenizer then says so).
#pragma once

#include <cstddef>
#include <string>

namespace vkrt {

// The most a scene file's line, and the whole file, may hold: reading stops past either
// (a SceneError at that line), and at the first byte that is not text.
inline constexpr std::size_t kMaxSceneLineBytes = std::size_t{1} << 20;    // 1 MiB
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 30;    // 1 GiB

// The text of the scene file `path`. Throws IoError when it cannot be opened or read,
// SceneError for a line or a file past the limits above, Interrupted when a signal stops a
// read (a FIFO).
std::string readSceneText(const std::string& path);

}  // namespace vkrt
