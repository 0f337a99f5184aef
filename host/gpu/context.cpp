// Headless Vulkan context: instance, device choice, compute queue, validation messages.
#include "gpu/context.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "util/errors.h"
#include "gpu/buffer_pool.h"
#include "gpu/device_error.h"
#include "util/timing.h"
#include "platform/library.h"

namespace vkrt {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
  std::uint32_t n = 0;
  vk::vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vk::vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

VkInstance createInstance(bool validation) {
  vk::loadGlobalFunctions();
  auto app = vk::make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "vkrt";
  app.apiVersion = VK_API_VERSION_1_1;
  auto info = vk::make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  const char* layer = kValidationLayer;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  if (validation) {
    if (!hasLayer(kValidationLayer))
      throw DeviceError("the Vulkan validation layer is not installed ('apt-get install vulkan-validationlayers')");
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
  }
  VkInstance instance = VK_NULL_HANDLE;
  VkResult r = vk::vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw DeviceError(std::string("no Vulkan driver found: ") + kVulkanInstallHint);
  VK_CHECK(r);
#ifdef VKRT_SANITIZE_BUILD
  // Sanitizer builds only: every library loaded so far (the Vulkan driver and what it loaded)
  // stays in memory for good. The loader unloads the driver when the instance is destroyed; a
  // 128-byte heap block allocated while it was loaded is then reachable only from unmapped
  // static data, and LeakSanitizer reports it as a leak from "<unknown module>" (measured with
  // Debian 12's Mesa 22.3.6: gone when nothing is unloaded). Pinned, the block stays
  // reachable, and leaks of our own still show.
  platform::pinLoadedLibraries();   // the driver is loaded now
#endif
  vk::loadInstanceFunctions(instance);
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  std::uint32_t n = 0;
  VK_CHECK(vk::vkEnumeratePhysicalDevices(instance, &n, nullptr));
  std::vector<VkPhysicalDevice> devices(n);
  VK_CHECK(vk::vkEnumeratePhysicalDevices(instance, &n, devices.data()));
  devices.resize(n);
  if (devices.empty()) throw DeviceError(std::string("no Vulkan device found: ") + kVulkanInstallHint);
  return devices;
}

// Default preference: a real GPU before a virtual one before the CPU (lavapipe).
int typeRank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 4;
    default: return 3;
  }
}

std::string deviceList(const std::vector<VkPhysicalDevice>& devices) {
  std::string s;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    VkPhysicalDeviceProperties p;
    vk::vkGetPhysicalDeviceProperties(devices[i], &p);
    s += "\n  " + std::to_string(i) + ": " + p.deviceName;
  }
  return s;
}

VkPhysicalDevice chooseDevice(const std::vector<VkPhysicalDevice>& devices, const std::string& wanted) {
  if (wanted.empty()) {
    return *std::min_element(devices.begin(), devices.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
      VkPhysicalDeviceProperties pa, pb;
      vk::vkGetPhysicalDeviceProperties(a, &pa);
      vk::vkGetPhysicalDeviceProperties(b, &pb);
      return typeRank(pa.deviceType) < typeRank(pb.deviceType);
    });
  }
  std::size_t index = 0;
  auto [end, ec] = std::from_chars(wanted.data(), wanted.data() + wanted.size(), index);
  if (ec == std::errc() && end == wanted.data() + wanted.size()) {
    if (index >= devices.size())
      throw DeviceError("no Vulkan device " + wanted + "; the devices are:" + deviceList(devices));
    return devices[index];
  }
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vk::vkGetPhysicalDeviceProperties(d, &p);
    if (std::string(p.deviceName).find(wanted) != std::string::npos) return d;
  }
  throw DeviceError("no Vulkan device named '" + wanted + "'; the devices are:" + deviceList(devices));
}

}  // namespace

void checkVk(VkResult result, const char* expr, const char* file, int line) {
  if (result == VK_SUCCESS) return;
  const char* base = std::strrchr(file, '/');
  std::string what = std::string(expr) + " failed: " + vk::resultName(result) + " (" + (base ? base + 1 : file) +
                     ":" + std::to_string(line) + ")";
  if (result == VK_ERROR_OUT_OF_HOST_MEMORY) throw OutOfMemory(what);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY)
    throw OutOfMemory(what + ": the scene needs more memory than the device has (--backend cpu uses the host's)");
  throw DeviceError(what);
}

const char* DeviceInfo::typeName() const {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

std::vector<DeviceInfo> listDevices() {
  VkInstance instance = createInstance(false);
  std::vector<DeviceInfo> out;
  try {
    for (VkPhysicalDevice d : physicalDevices(instance)) {
      VkPhysicalDeviceProperties p;
      vk::vkGetPhysicalDeviceProperties(d, &p);
      out.push_back({p.deviceName, p.deviceType});
    }
  } catch (...) {
    vk::vkDestroyInstance(instance, nullptr);
    throw;
  }
  vk::vkDestroyInstance(instance, nullptr);
  return out;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    static_cast<Context*>(user)->validationMessages_.fetch_add(1);
    std::fprintf(stderr, "vkrt: Vulkan validation: %s\n", data->pMessage);
  }
  return VK_FALSE;
}


Context::Context(const ContextOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  instance_ = createInstance(options.validation);
  try {
    if (options.validation && vk::vkCreateDebugUtilsMessengerEXT) {
      auto info =
          vk::make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
      info.messageSeverity =
          VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
      info.pfnUserCallback = &Context::onMessage;
      info.pUserData = this;
      VK_CHECK(vk::vkCreateDebugUtilsMessengerEXT(instance_, &info, nullptr, &messenger_));
      destroyMessenger_ = vk::vkDestroyDebugUtilsMessengerEXT;
    }
    instanceSeconds_ = secondsSince(t0);
    t0 = std::chrono::steady_clock::now();

    physical_ = chooseDevice(physicalDevices(instance_), options.device);
    vk::vkGetPhysicalDeviceProperties(physical_, &properties_);
    vk::vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

    std::uint32_t n = 0;
    vk::vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vk::vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, families.data());
    bool found = false;
    for (std::uint32_t i = 0; i < n && !found; ++i)
      if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
        queueFamily_ = i;
        found = true;
      }
    if (!found) throw DeviceError(std::string("Vulkan device '") + properties_.deviceName + "' has no compute queue");

    float priority = 1.0f;
    auto queueInfo = vk::make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    auto deviceInfo = vk::make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    VK_CHECK(vk::vkCreateDevice(physical_, &deviceInfo, nullptr, &device_));
    vk::vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    pipelines_ = std::make_unique<PipelineCache>(device_);
    scenePool_ = std::make_unique<BufferPool>();
    deviceSeconds_ = secondsSince(t0);
  } catch (...) {
    if (messenger_) destroyMessenger_(instance_, messenger_, nullptr);
    vk::vkDestroyInstance(instance_, nullptr);
    throw;
  }
}

Context::~Context() {
  if (device_) {
    vk::vkDeviceWaitIdle(device_);
    pipelines_.reset();
    scenePool_.reset();
    vk::vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) destroyMessenger_(instance_, messenger_, nullptr);
  vk::vkDestroyInstance(instance_, nullptr);
}

}  // namespace vkrt
