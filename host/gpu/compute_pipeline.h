// A compute pipeline over buffers at bindings 0..N-1 of set 0 (storage buffers or uniform
// texel buffers), with uint specialization constants (ids 0..) and a push-constant
// block, plus the command buffer and fence to run it synchronously. The compiled pipeline
// comes from the context's PipelineCache (made there the first time); the descriptor set,
// the command buffer and the fence are this object's own.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "gpu/buffer.h"

namespace vkrt {

// Throws DeviceError when a compute shader on a device of `limits` (named `deviceName`) cannot
// have the bindings `types`: more storage buffers, storage texel buffers (storage images, to
// Vulkan) or resources in all than the device allows a shader stage. Every device lavapipe
// or a desktop GPU offers allows them; Vulkan's minimums (4 storage buffers, 4 storage
// images, 128 resources) do not.
void checkBindingLimits(const VkPhysicalDeviceLimits& limits, const char* deviceName,
                        const std::vector<VkDescriptorType>& types);

class ComputePipeline {
 public:
  ComputePipeline(const Context& context, const std::uint32_t* spirv, std::size_t spirvBytes,
                  const std::vector<VkDescriptorType>& bindingTypes, const std::vector<std::uint32_t>& specConstants,
                  std::uint32_t pushConstantBytes);
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Makes the context's pipeline of these arguments ahead of the render that will construct
  // one with them (which then takes it from the PipelineCache), e.g. on another thread while
  // the scene's BVH builds. Throws as the constructor does.
  static void prepare(const Context& context, const std::uint32_t* spirv, std::size_t spirvBytes,
                      const std::vector<VkDescriptorType>& bindingTypes,
                      const std::vector<std::uint32_t>& specConstants, std::uint32_t pushConstantBytes);

  // A storage buffer at `binding`.
  void bind(std::uint32_t binding, const Buffer& buffer);
  // A storage texel buffer at `binding`: a view of `buffer` as texels of `format`
  // (`texelBytes` each). The pipeline owns the view.
  void bindTexels(std::uint32_t binding, const Buffer& buffer, VkFormat format, std::size_t texelBytes);

  // Records: an optional fill of `clear` (first 4 bytes to 0), push constants, one dispatch of
  // `groups` workgroups (x), and a barrier that makes the shader's writes visible to the host;
  // then submits and waits.
  void run(const void* pushConstants, std::uint32_t groups, const Buffer* clear = nullptr);

 private:
  // Destroys every handle made so far; safe to call on a partly constructed pipeline.
  void release();
  void write(std::uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* buffer,
             const VkBufferView* view);
  const Context& context_;
  VkDevice device_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  std::vector<VkBufferView> views_;
  std::uint32_t pushConstantBytes_;
};

}  // namespace vkrt
