// The scene buffers of a context's last render, kept for its next (SceneUpload): on lavapipe
// a path render whose scene arrays were new buffers, made after an earlier render's
// dispatches, traced 15-25% slower than one given that render's buffers again
// (bench/README.md, "`--time` against `--spp`, and the scene's buffers"). A buffer is reused
// at the same size only; texelPaddedBytes (scene_upload.cpp) makes sizes few: each array of
// a small scene takes 192 KiB.
#pragma once

#include <cstddef>
#include <mutex>
#include <vector>

#include "gpu/buffer.h"

namespace vkrt {

class BufferPool {
 public:
  // A buffer of `bytes`: one kept (its old contents still in it), or a new one.
  Buffer take(const Context& context, std::size_t bytes);
  // Keeps `buffers` for the takes that follow, in place of any kept before (so that the pool
  // holds at most one scene's arrays).
  void keep(std::vector<Buffer> buffers);
  // Frees the kept buffers of a size not among `sizes` (before an upload of those sizes, so
  // that two large scenes' arrays are not held at once).
  void retainSizes(const std::vector<std::size_t>& sizes);
  std::size_t kept() const;

 private:
  mutable std::mutex mutex_;
  std::vector<Buffer> kept_;
};

}  // namespace vkrt
