// Host-visible storage buffers.
#include "gpu/buffer.h"

#include <algorithm>
#include <utility>

#include "gpu/device_error.h"

namespace vkrt {
namespace {

constexpr std::size_t kMinBufferBytes = 256;

// A memory type with all of `required`, and as many of `preferred` as possible.
std::uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& mem, std::uint32_t allowed,
                               VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  int best = -1, bestScore = -1;
  for (std::uint32_t i = 0; i < mem.memoryTypeCount; ++i) {
    VkMemoryPropertyFlags f = mem.memoryTypes[i].propertyFlags;
    if (!(allowed & (1u << i)) || (f & required) != required) continue;
    int score = __builtin_popcount(f & preferred);
    if (score > bestScore) {
      best = static_cast<int>(i);
      bestScore = score;
    }
  }
  if (best < 0) throw DeviceError("the Vulkan device has no host-visible memory for buffers");
  return static_cast<std::uint32_t>(best);
}

}  // namespace

Buffer::Buffer(const Context& context, std::size_t bytes, bool readback)
    : device_(context.device()), size_(std::max(bytes, kMinBufferBytes)) {
  auto info = vk::make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = size_;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT |
               VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vk::vkCreateBuffer(device_, &info, nullptr, &buffer_));
  try {
    VkMemoryRequirements req;
    vk::vkGetBufferMemoryRequirements(device_, buffer_, &req);
    auto alloc = vk::make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = chooseMemoryType(
        context.memoryProperties(), req.memoryTypeBits,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
        readback ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vk::vkAllocateMemory(device_, &alloc, nullptr, &memory_));
    VK_CHECK(vk::vkBindBufferMemory(device_, buffer_, memory_, 0));
    VK_CHECK(vk::vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    filled_ = size_;   // new memory is not known to be zero (fill)
  } catch (...) {
    if (memory_) vk::vkFreeMemory(device_, memory_, nullptr);
    vk::vkDestroyBuffer(device_, buffer_, nullptr);
    throw;
  }
}

Buffer::Buffer(Buffer&& o) noexcept
    : device_(o.device_), buffer_(o.buffer_), memory_(o.memory_), size_(o.size_), mapped_(o.mapped_),
      filled_(o.filled_) {
  o.buffer_ = VK_NULL_HANDLE;
  o.memory_ = VK_NULL_HANDLE;
  o.mapped_ = nullptr;
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  std::swap(device_, o.device_);
  std::swap(buffer_, o.buffer_);
  std::swap(memory_, o.memory_);
  std::swap(size_, o.size_);
  std::swap(mapped_, o.mapped_);
  std::swap(filled_, o.filled_);
  return *this;   // o frees what this held
}

Buffer::~Buffer() {
  if (buffer_) vk::vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vk::vkFreeMemory(device_, memory_, nullptr);   // unmaps too
}

}  // namespace vkrt
