// Run-time loading of the Vulkan loader library.
#include "gpu/vulkan_api.h"

#include <string>

#include "gpu/device_error.h"
#include "platform/library.h"

namespace vkrt::vk {

void loadGlobalFunctions() {
  if (vkGetInstanceProcAddr) return;
  void* lib = platform::openVulkanLoader();
  if (!lib)
    throw DeviceError(std::string("the Vulkan loader (") + platform::vulkanLoaderName() + ") is not installed: " +
#ifdef _WIN32
                      "install your GPU's driver, which brings it, or a Vulkan runtime; or use --backend cpu");
#else
                      "'apt-get install libvulkan1 mesa-vulkan-drivers', or use --backend cpu");
#endif
  vkGetInstanceProcAddr =
      reinterpret_cast<PFN_vkGetInstanceProcAddr>(platform::librarySymbol(lib, "vkGetInstanceProcAddr"));
  if (!vkGetInstanceProcAddr) throw DeviceError("the Vulkan loader has no vkGetInstanceProcAddr");
#define VKRT_VK_LOAD(name)                                                                    \
  name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(VK_NULL_HANDLE, #name));        \
  if (!name) throw DeviceError("the Vulkan loader lacks " #name);
  VKRT_VK_GLOBAL_FUNCTIONS(VKRT_VK_LOAD)
#undef VKRT_VK_LOAD
}

void loadInstanceFunctions(VkInstance instance) {
#define VKRT_VK_LOAD(name)                                                              \
  name = reinterpret_cast<PFN_##name>(vkGetInstanceProcAddr(instance, #name));        \
  if (!name) throw DeviceError("the Vulkan instance lacks " #name);
  VKRT_VK_INSTANCE_FUNCTIONS(VKRT_VK_LOAD)
#undef VKRT_VK_LOAD
  vkCreateDebugUtilsMessengerEXT = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  vkDestroyDebugUtilsMessengerEXT = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
}

const char* resultName(VkResult r) {
  switch (r) {
#define VKRT_CASE(x) \
  case x: return #x;
    VKRT_CASE(VK_SUCCESS)
    VKRT_CASE(VK_NOT_READY)
    VKRT_CASE(VK_TIMEOUT)
    VKRT_CASE(VK_INCOMPLETE)
    VKRT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    VKRT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    VKRT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    VKRT_CASE(VK_ERROR_DEVICE_LOST)
    VKRT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    VKRT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    VKRT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    VKRT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    VKRT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    VKRT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    VKRT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    VKRT_CASE(VK_ERROR_FRAGMENTED_POOL)
    VKRT_CASE(VK_ERROR_UNKNOWN)
    VKRT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    VKRT_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef VKRT_CASE
    default: return "VK_ERROR_(unnamed)";
  }
}

}  // namespace vkrt::vk
