// Libraries opened at run time: the Vulkan loader, which vkrt opens itself so that it starts
// (and says what to install) on a machine without one.
#pragma once

namespace vkrt::platform {

// The Vulkan loader's file name as this system calls it (libvulkan.so.1, vulkan-1.dll,
// libvulkan.1.dylib), for messages.
const char* vulkanLoaderName();

// Opens the Vulkan loader, or returns nullptr when it is not installed.
void* openVulkanLoader();

// The address of `name` in a library that openVulkanLoader opened, or nullptr.
void* librarySymbol(void* library, const char* name);

// Sanitizer builds (Linux): keeps every library loaded so far in memory for good (context.cpp
// says why). Elsewhere it does nothing.
void pinLoadedLibraries();

}  // namespace vkrt::platform
