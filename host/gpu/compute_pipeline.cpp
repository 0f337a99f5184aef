// Compute pipeline creation and synchronous dispatch.
#include "gpu/compute_pipeline.h"

#include "gpu/context.h"
#include "gpu/device_error.h"
#include "gpu/pipeline_cache.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace vkrt {

namespace {

// The set layout, pipeline layout and pipeline of `key`: all three made, or none (throws).
CompiledPipeline compile(VkDevice device, const PipelineKey& key) {
  const auto bindingCount = static_cast<std::uint32_t>(key.bindingTypes.size());
  CompiledPipeline made;
  auto destroy = [&]() {
    if (made.pipeline) vk::vkDestroyPipeline(device, made.pipeline, nullptr);
    if (made.layout) vk::vkDestroyPipelineLayout(device, made.layout, nullptr);
    if (made.setLayout) vk::vkDestroyDescriptorSetLayout(device, made.setLayout, nullptr);
  };
  try {
    std::vector<VkDescriptorSetLayoutBinding> bindings(bindingCount);
    for (std::uint32_t i = 0; i < bindingCount; ++i)
      bindings[i] = {i, key.bindingTypes[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    auto setInfo = vk::make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    setInfo.bindingCount = bindingCount;
    setInfo.pBindings = bindings.data();
    VK_CHECK(vk::vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &made.setLayout));

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, key.pushConstantBytes};
    auto layoutInfo = vk::make<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &made.setLayout;
    layoutInfo.pushConstantRangeCount = key.pushConstantBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VK_CHECK(vk::vkCreatePipelineLayout(device, &layoutInfo, nullptr, &made.layout));

    auto moduleInfo = vk::make<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    moduleInfo.codeSize = key.spirvBytes;
    moduleInfo.pCode = key.spirv;
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vk::vkCreateShaderModule(device, &moduleInfo, nullptr, &module));
    const std::vector<std::uint32_t>& specConstants = key.specConstants;
    std::vector<VkSpecializationMapEntry> entries(specConstants.size());
    for (std::uint32_t i = 0; i < entries.size(); ++i)
      entries[i] = {i, i * static_cast<std::uint32_t>(sizeof(std::uint32_t)), sizeof(std::uint32_t)};
    VkSpecializationInfo spec{static_cast<std::uint32_t>(entries.size()), entries.data(),
                              specConstants.size() * sizeof(std::uint32_t), specConstants.data()};
    auto pipelineInfo = vk::make<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    pipelineInfo.stage =
        vk::make<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module;
    pipelineInfo.stage.pName = "main";
    pipelineInfo.stage.pSpecializationInfo = specConstants.empty() ? nullptr : &spec;
    pipelineInfo.layout = made.layout;
    VkResult r = vk::vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &made.pipeline);
    vk::vkDestroyShaderModule(device, module, nullptr);
    VK_CHECK(r);
  } catch (...) {
    destroy();
    throw;
  }
  return made;
}

// The context's pipeline of `key`, made now (its bindings checked against the device's limits)
// if it has none. It lives in the context's cache, not in `key`: a pointer, because GCC 14's
// -Wdangling-reference takes a reference returned from a call given a temporary key (as the
// callers below give it) for one into that temporary.
const CompiledPipeline* compiled(const Context& context, const PipelineKey& key) {
  return &context.pipelines().get(key, [&] {
    checkBindingLimits(context.properties().limits, context.properties().deviceName, key.bindingTypes);
    return compile(context.device(), key);
  });
}

}  // namespace

void checkBindingLimits(const VkPhysicalDeviceLimits& limits, const char* deviceName,
                        const std::vector<VkDescriptorType>& types) {
  const auto count = [&](VkDescriptorType type) {
    return static_cast<std::uint32_t>(std::count(types.begin(), types.end(), type));
  };
  const struct {
    std::uint32_t used, allowed;
    const char *what, *fewer;   // fewer: the --reads that binds fewer of them, if one does
  } checks[] = {
      {count(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER), limits.maxPerStageDescriptorStorageBuffers, "storage buffers",
       "--reads texel"},
      {count(VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER), limits.maxPerStageDescriptorStorageImages,
       "storage texel buffers (storage images)", "--reads storage"},
      {static_cast<std::uint32_t>(types.size()), limits.maxPerStageResources, "resources", nullptr},
  };
  for (const auto& c : checks)
    if (c.used > c.allowed)
      throw DeviceError("the Vulkan device '" + std::string(deviceName) + "' allows a compute shader " +
                        std::to_string(c.allowed) + " " + c.what + ", and vkrt's shader needs " +
                        std::to_string(c.used) + " (" +
                        (c.fewer ? c.fewer + std::string(" needs fewer; ") : std::string()) +
                        "--backend cpu needs no device)");
}

void ComputePipeline::prepare(const Context& context, const std::uint32_t* spirv, std::size_t spirvBytes,
                              const std::vector<VkDescriptorType>& bindingTypes,
                              const std::vector<std::uint32_t>& specConstants, std::uint32_t pushConstantBytes) {
  compiled(context, PipelineKey{spirv, spirvBytes, bindingTypes, specConstants, pushConstantBytes});
}

ComputePipeline::ComputePipeline(const Context& context, const std::uint32_t* spirv, std::size_t spirvBytes,
                                 const std::vector<VkDescriptorType>& bindingTypes,
                                 const std::vector<std::uint32_t>& specConstants, std::uint32_t pushConstantBytes)
    : context_(context), device_(context.device()), pushConstantBytes_(pushConstantBytes) {
  try {
    const CompiledPipeline* made =
        compiled(context, PipelineKey{spirv, spirvBytes, bindingTypes, specConstants, pushConstantBytes});
    setLayout_ = made->setLayout;
    layout_ = made->layout;
    pipeline_ = made->pipeline;

    std::vector<VkDescriptorPoolSize> poolSizes;
    for (VkDescriptorType type : bindingTypes) {
      auto it = std::find_if(poolSizes.begin(), poolSizes.end(), [&](const auto& p) { return p.type == type; });
      if (it == poolSizes.end())
        poolSizes.push_back({type, 1});
      else
        ++it->descriptorCount;
    }
    auto poolInfo = vk::make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = static_cast<std::uint32_t>(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    VK_CHECK(vk::vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));
    auto allocInfo = vk::make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
    allocInfo.descriptorPool = pool_;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &setLayout_;
    VK_CHECK(vk::vkAllocateDescriptorSets(device_, &allocInfo, &set_));

    auto cmdPoolInfo = vk::make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    cmdPoolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    cmdPoolInfo.queueFamilyIndex = context.queueFamily();
    VK_CHECK(vk::vkCreateCommandPool(device_, &cmdPoolInfo, nullptr, &commandPool_));
    auto cmdInfo = vk::make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    cmdInfo.commandPool = commandPool_;
    cmdInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cmdInfo.commandBufferCount = 1;
    VK_CHECK(vk::vkAllocateCommandBuffers(device_, &cmdInfo, &commands_));
    auto fenceInfo = vk::make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VK_CHECK(vk::vkCreateFence(device_, &fenceInfo, nullptr, &fence_));
  } catch (...) {
    release();   // the destructor does not run for an object whose constructor threw
    throw;
  }
}

ComputePipeline::~ComputePipeline() { release(); }

void ComputePipeline::release() {
  for (VkBufferView v : views_) vk::vkDestroyBufferView(device_, v, nullptr);
  views_.clear();
  if (fence_) vk::vkDestroyFence(device_, fence_, nullptr);
  if (commandPool_) vk::vkDestroyCommandPool(device_, commandPool_, nullptr);
  if (pool_) vk::vkDestroyDescriptorPool(device_, pool_, nullptr);
  // (the pipeline and its layouts belong to the context's PipelineCache)
  fence_ = VK_NULL_HANDLE;
  commandPool_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
}

void ComputePipeline::write(std::uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* buffer,
                            const VkBufferView* view) {
  auto write = vk::make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  write.pBufferInfo = buffer;
  write.pTexelBufferView = view;
  vk::vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void ComputePipeline::bind(std::uint32_t binding, const Buffer& buffer) {
  VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
  write(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &info, nullptr);
}

void ComputePipeline::bindTexels(std::uint32_t binding, const Buffer& buffer, VkFormat format,
                                 std::size_t texelBytes) {
  auto info = vk::make<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
  info.buffer = buffer.handle();
  info.format = format;
  info.offset = 0;
  info.range = buffer.size() / texelBytes * texelBytes;
  VkBufferView view = VK_NULL_HANDLE;
  VK_CHECK(vk::vkCreateBufferView(device_, &info, nullptr, &view));
  views_.push_back(view);
  write(binding, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, nullptr, &view);
}

void ComputePipeline::run(const void* pushConstants, std::uint32_t groups, const Buffer* clear) {
  VK_CHECK(vk::vkResetCommandBuffer(commands_, 0));
  auto begin = vk::make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vk::vkBeginCommandBuffer(commands_, &begin));
  // Earlier dispatches' writes (a suspended pixel's state) and the host's writes to the
  // mappings must be visible to this dispatch's reads.
  auto earlier = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  earlier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
  earlier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  vk::vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &earlier, 0,
                           nullptr, 0, nullptr);
  if (clear) {
    vk::vkCmdFillBuffer(commands_, clear->handle(), 0, 4, 0);
    // The cleared counter must be in place before the shader increments it.
    auto fill = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    fill.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    fill.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vk::vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                             &fill, 0, nullptr, 0, nullptr);
  }
  vk::vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vk::vkCmdBindDescriptorSets(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
  if (pushConstantBytes_)
    vk::vkCmdPushConstants(commands_, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes_, pushConstants);
  vk::vkCmdDispatch(commands_, groups, 1, 1);
  // The host reads the shader's writes (pixels, counters) through the mapping after the fence.
  auto toHost = vk::make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vk::vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                           0, nullptr, 0, nullptr);
  VK_CHECK(vk::vkEndCommandBuffer(commands_));
  auto submit = vk::make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  VK_CHECK(vk::vkQueueSubmit(context_.queue(), 1, &submit, fence_));
  VK_CHECK(vk::vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
  VK_CHECK(vk::vkResetFences(device_, 1, &fence_));
}

}  // namespace vkrt
