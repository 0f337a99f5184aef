// The Vulkan entry points vkrt uses, loaded at run time from the loader library, so that
// vkrt starts (and its CPU backend works) on a machine without Vulkan, and a missing loader
// or driver is an error that says what to install. The only header that includes vulkan.h.
#pragma once

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

namespace vkrt::vk {

#define VKRT_VK_GLOBAL_FUNCTIONS(X) \
  X(vkCreateInstance)               \
  X(vkEnumerateInstanceLayerProperties)

#define VKRT_VK_INSTANCE_FUNCTIONS(X)          \
  X(vkDestroyInstance)                         \
  X(vkEnumeratePhysicalDevices)                \
  X(vkGetPhysicalDeviceProperties)             \
  X(vkGetPhysicalDeviceQueueFamilyProperties)  \
  X(vkGetPhysicalDeviceMemoryProperties)       \
  X(vkCreateDevice)                            \
  X(vkDestroyDevice)                           \
  X(vkGetDeviceQueue)                          \
  X(vkCreateBuffer)                            \
  X(vkDestroyBuffer)                           \
  X(vkGetBufferMemoryRequirements)             \
  X(vkAllocateMemory)                          \
  X(vkFreeMemory)                              \
  X(vkBindBufferMemory)                        \
  X(vkMapMemory)                               \
  X(vkCreateShaderModule)                      \
  X(vkDestroyShaderModule)                     \
  X(vkCreateDescriptorSetLayout)               \
  X(vkDestroyDescriptorSetLayout)              \
  X(vkCreatePipelineLayout)                    \
  X(vkDestroyPipelineLayout)                   \
  X(vkCreateComputePipelines)                  \
  X(vkDestroyPipeline)                         \
  X(vkCreateDescriptorPool)                    \
  X(vkDestroyDescriptorPool)                   \
  X(vkAllocateDescriptorSets)                  \
  X(vkUpdateDescriptorSets)                    \
  X(vkCreateCommandPool)                       \
  X(vkDestroyCommandPool)                      \
  X(vkAllocateCommandBuffers)                  \
  X(vkBeginCommandBuffer)                      \
  X(vkEndCommandBuffer)                        \
  X(vkResetCommandBuffer)                      \
  X(vkCmdBindPipeline)                         \
  X(vkCmdBindDescriptorSets)                   \
  X(vkCmdPushConstants)                        \
  X(vkCmdDispatch)                             \
  X(vkCmdPipelineBarrier)                      \
  X(vkCmdFillBuffer)                           \
  X(vkQueueSubmit)                             \
  X(vkCreateFence)                             \
  X(vkDestroyFence)                            \
  X(vkWaitForFences)                           \
  X(vkResetFences)                             \
  X(vkDeviceWaitIdle)                          \
  X(vkCreateBufferView)                        \
  X(vkDestroyBufferView)

#define VKRT_VK_DECLARE(name) inline PFN_##name name = nullptr;
inline PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
VKRT_VK_GLOBAL_FUNCTIONS(VKRT_VK_DECLARE)
VKRT_VK_INSTANCE_FUNCTIONS(VKRT_VK_DECLARE)
inline PFN_vkCreateDebugUtilsMessengerEXT vkCreateDebugUtilsMessengerEXT = nullptr;
inline PFN_vkDestroyDebugUtilsMessengerEXT vkDestroyDebugUtilsMessengerEXT = nullptr;
#undef VKRT_VK_DECLARE

// Opens the loader library and fetches the global functions. Throws DeviceError.
void loadGlobalFunctions();
// Fetches the instance-level functions (device functions go through the loader's trampolines).
void loadInstanceFunctions(VkInstance instance);

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" and so on.
const char* resultName(VkResult result);

// A Vulkan struct of type `sType`, every other member zero (pNext null):
// `auto info = vk::make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);`. Written
// `VkBufferCreateInfo info{VK_STRUCTURE_TYPE_...}` the members after sType are zero too, but
// clang's -Wmissing-field-initializers (in -Wextra) reports each such struct.
template <class T>
T make(VkStructureType sType) {
  T s{};
  s.sType = sType;
  return s;
}

}  // namespace vkrt::vk
