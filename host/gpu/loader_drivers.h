// The Vulkan loader's drivers: which ones a run asks the loader to skip. The loader opens every
// installed driver when an instance is made, and each loads its libraries and looks for its
// devices (on Debian 12: Intel's two and Radeon's, which with the device-select layer cost
// every run some milliseconds: bench/README.md, "Fixed cost of the Vulkan backend"). Those
// drivers find GPUs only through DRM render nodes (/dev/dri/renderD*):
// where there is none, they can find nothing, and vkrt asks the loader to skip them and
// Mesa's device-select layer (which only orders GPUs). A user's own choice of drivers or
// layers through the loader's variables is left as it is, and so is every driver that may
// find a device without a render node (lavapipe, NVIDIA's, any other).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vkrt {

// The loader variables to set (name, value), given the environment (`lookup` returns nullptr
// for an unset variable) and whether the machine has a DRM render node. Empty: set nothing.
std::vector<std::pair<std::string, std::string>> loaderDriverSettings(
    const std::function<const char*(const char*)>& lookup, bool hasRenderNode);

// Whether /dev/dri holds a render node (or may: a /dev/dri that cannot be read counts as one).
bool hasDrmRenderNode();

// Sets loaderDriverSettings(getenv, hasDrmRenderNode()) in the process environment. Call it
// before any thread starts and before the first Vulkan call (main does).
void skipDriversWithoutDevices();

}  // namespace vkrt
