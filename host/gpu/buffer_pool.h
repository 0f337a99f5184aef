// The scene buffers of a context's last render, kept for its next (SceneUpload): on lavapipe
// a path render whose scene arrays were new buffers, made after an earlier render's
// dispatches, traced slower than one given that render's buffers again (by how much:
// bench/README.md, "`--time` against `--spp`, and the scene's buffers"). A buffer is reused
// at the same size only; texelPaddedBytes (scene_upload.cpp) makes sizes few: each array of
// a small scene takes 192 KiB.
#pragma once

#include <cstddef>
#include <mutex>
#include <vector>

#include "gpu/buffer.h"

namespace vkrt {

// The most a pool keeps: the arrays of a larger scene are freed with it (the gain was measured
// on small scenes; a large scene's arrays would stay held while `vkrt --watch` waits).
inline constexpr std::size_t kMaxPooledBytes = std::size_t{64} << 20;

class BufferPool {
 public:
  explicit BufferPool(std::size_t maxBytes = kMaxPooledBytes) : maxBytes_(maxBytes) {}
  // A buffer of `bytes`: one kept (its old contents still in it), or a new one.
  Buffer take(const Context& context, std::size_t bytes);
  // Keeps `buffers` for the takes that follow, in place of any kept before (so that the pool
  // holds at most one scene's arrays), or none of them when they add up to more than maxBytes.
  void keep(std::vector<Buffer> buffers);
  // Frees the kept buffers that an upload taking `sizes` will not take (at most as many of a
  // size as `sizes` lists), before it, so that two scenes' arrays are not held at once.
  void retainSizes(const std::vector<std::size_t>& sizes);
  std::size_t kept() const;

 private:
  std::size_t maxBytes_;
  mutable std::mutex mutex_;
  std::vector<Buffer> kept_;
};

}  // namespace vkrt
