// A headless Vulkan context: instance (no surface extensions), one physical device, a
// logical device with one compute queue, and optionally the validation layer.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "gpu/pipeline_cache.h"
#include "gpu/vulkan_api.h"

namespace vkrt {

// Checks a VkResult; throws DeviceError naming the call, the result and where (OutOfMemory
// for VK_ERROR_OUT_OF_HOST_MEMORY and VK_ERROR_OUT_OF_DEVICE_MEMORY).
#define VK_CHECK(expr) ::vkrt::checkVk((expr), #expr, __FILE__, __LINE__)
void checkVk(VkResult result, const char* expr, const char* file, int line);

struct ContextOptions {
  std::string device;        // "" (choose), an index, or part of a device name
  bool validation = false;   // enable VK_LAYER_KHRONOS_validation and count its messages
};

struct DeviceInfo {
  std::string name;
  VkPhysicalDeviceType type;
  const char* typeName() const;
};

// Lists the Vulkan devices (loads the loader, makes a throwaway instance). Throws DeviceError.
std::vector<DeviceInfo> listDevices();

class BufferPool;

class Context {
 public:
  explicit Context(const ContextOptions& options);   // throws DeviceError
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  // A CPU device (lavapipe), for which the renderers choose variants and work sizes apart.
  bool isCpuDevice() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
  // Validation messages (warnings and errors) so far; each is also printed on stderr.
  int validationMessages() const { return validationMessages_.load(); }
  double instanceSeconds() const { return instanceSeconds_; }
  double deviceSeconds() const { return deviceSeconds_; }
  // The compiled pipelines kept for the renders on this context (their users on one thread
  // at a time, or through the cache's own lock).
  PipelineCache& pipelines() const { return *pipelines_; }
  // The scene buffers of the last render, for the next (SceneUpload).
  BufferPool& scenePool() const { return *scenePool_; }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT*, void*);
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  // This instance's own: the global pointer (gpu/vulkan_api.h) is the last instance's, null
  // when a later context in the process was made without validation.
  PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger_ = nullptr;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  std::atomic<int> validationMessages_{0};
  double instanceSeconds_ = 0, deviceSeconds_ = 0;
  std::unique_ptr<PipelineCache> pipelines_;   // made with the device, destroyed before it
  std::unique_ptr<BufferPool> scenePool_;      // likewise
};

}  // namespace vkrt
