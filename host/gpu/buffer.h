// A buffer (storage, uniform or texel) in host-visible memory, mapped for its whole life: uploads are a memcpy
// into the mapping (no staging copy), readback a read from it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

#include "gpu/context.h"

namespace vkrt {

// `bytes` rounded up to a count of 64 KiB blocks that is not a power of two and is at least 3
// (Buffer::withContents).
inline std::size_t texelPaddedBytes(std::size_t bytes) {
  constexpr std::size_t kBlock = 65536;
  std::size_t blocks = std::max<std::size_t>((bytes + kBlock - 1) / kBlock, 3);
  while ((blocks & (blocks - 1)) == 0) ++blocks;
  return blocks * kBlock;
}

class Buffer {
 public:
  // `bytes` of 0 still makes a small buffer: Vulkan binds no empty buffer.
  Buffer(const Context& context, std::size_t bytes, bool readback = false);
  ~Buffer();
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // A buffer holding `items`; with `texels` (an array the shaders may read through a texel
  // view) zero-padded to texelPaddedBytes. Lavapipe compiles a shader again for each new
  // combination of two properties of its texel buffers' sizes (Mesa 22.3,
  // lp_sampler_static_texture_state): whether the buffer's size is a power of two, and
  // whether bits 8-15 of the view's size are zero (read through a union as the last mip
  // level). Scenes whose arrays differed in either compiled the same shader twice (0.2-0.5 s
  // each); a count of 64 KiB blocks that is not a power of two is the same for every scene.
  template <class T>
  static Buffer withContents(const Context& context, const std::vector<T>& items, bool texels = false) {
    const std::size_t bytes = items.size() * sizeof(T);
    Buffer b(context, texels ? texelPaddedBytes(bytes) : bytes);
    if (!items.empty()) std::memcpy(b.mapped(), items.data(), bytes);
    return b;
  }
  Buffer(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_; }
  std::size_t size() const { return size_; }
  void* mapped() const { return mapped_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  std::size_t size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace vkrt
