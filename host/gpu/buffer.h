// A buffer (storage or texel) in host-visible memory, mapped for its whole life: uploads are a memcpy
// into the mapping (no staging copy), readback a read from it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "gpu/context.h"

namespace vkrt {

class Buffer {
 public:
  // `bytes` of 0 still makes a small buffer: Vulkan binds no empty buffer.
  Buffer(const Context& context, std::size_t bytes, bool readback = false);
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // A buffer holding `items`, of their size (the scene's texel arrays are padded and pooled
  // instead: SceneUpload).
  template <class T>
  static Buffer withContents(const Context& context, const std::vector<T>& items) {
    Buffer b(context, items.size() * sizeof(T));
    b.fill(items.data(), items.size() * sizeof(T));
    return b;
  }
  // `bytes` from `data` at the start, and zeros from there to the end: what an earlier fill
  // wrote (a buffer used again, BufferPool), and on a new buffer whatever its memory held.
  // Lavapipe takes a buffer's memory from malloc, which hands back freed memory as it was: the
  // bytes past a scene array's data, which the path shader reads (the record after the last
  // triangle), held what the process had freed there, and the denormal floats among them
  // (pointers' upper halves) slowed every ray, as the heap's layout fell: by the length of the
  // output's name (bench/README.md, "`--time` against `--spp`, and the scene's buffers").
  void fill(const void* data, std::size_t bytes) {
    if (bytes > 0) std::memcpy(mapped_, data, bytes);
    if (filled_ > bytes) std::memset(static_cast<char*>(mapped_) + bytes, 0, filled_ - bytes);
    filled_ = bytes;
  }
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_; }
  std::size_t size() const { return size_; }
  void* mapped() const { return mapped_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  std::size_t size_ = 0;
  void* mapped_ = nullptr;
  std::size_t filled_ = 0;   // the bytes that may be other than zero: the last fill's; a new buffer's all
};

}  // namespace vkrt
