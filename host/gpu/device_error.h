// Errors of the Vulkan environment (no loader, no driver, no such device, a failed call) and
// scenes beyond the Vulkan backend's or the device's limits: exit status 3. The scene itself
// is valid, and --backend cpu renders it.
#pragma once

#include <stdexcept>
#include <string>

namespace vkrt {

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What to install or set when no Vulkan device can be used.
inline constexpr const char* kVulkanInstallHint =
    "install a Vulkan driver: on Debian, 'apt-get install mesa-vulkan-drivers' gives lavapipe, which runs "
    "on the CPU (force it with VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json); or use "
    "--backend cpu";

}  // namespace vkrt
