// Which compiled variant of a shader a render uses. A specialised variant leaves out what the
// scene does not use (faster on lavapipe) but is compiled for each new combination of
// features, which takes longer than a small render (bench/README.md, "Latest figures: first
// render, shader variants, responsiveness", has both). The
// general variant has every feature in, the same for every scene, so it is compiled once
// per machine (by the first render that uses it) and then comes from the driver's shader
// cache. Under ShaderVariant::Auto a render takes its specialised variant when the render is
// long enough to pay for the compile, or, on a CPU device, when that one has been compiled on
// this machine before (the index below); the general one otherwise. Both give the same image
// bit for bit on lavapipe (a GPU's compiler may fuse multiply-adds differently in the two: on
// an H200 the path shader's differed by up to 4e-6 of a value).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/vulkan_api.h"

namespace vkrt {

// A render's estimated rays from which the specialised variant pays for its compile on a
// CPU device (lavapipe, two cores): the compile's time over the trace time it saves per
// estimated ray, for each shader, as measured on the course scenes and on the 16 CSE 168
// scenes as previews (bench/README.md, "Latest figures: first render, shader variants,
// responsiveness").
inline constexpr double kSpecializeWhittedAboveRays = 30e6;
inline constexpr double kSpecializePathAboveRays = 20e6;
// The same on a GPU, from an H200's compile times and the trace time a specialised variant
// saved per estimated ray there (doc/device-check.md, "Figures": its variant table and "The
// variant table settles the GPU's rule").
inline constexpr double kSpecializeGpuAboveRays = 4e10;

bool specializationPays(bool cpuDevice, double estimatedRays, bool pathShader);

// ShaderVariant::Auto's choice: the specialised variant (key `specializedKey`) where it pays
// for its compile, or, on a CPU device, where the index says it is compiled already. A GPU
// does not take it for being compiled: its trace gains next to nothing there, and so the
// variant, and the bits, of a command depend on the command alone.
bool autoTakesSpecialised(bool cpuDevice, double estimatedRays, bool pathShader, std::uint64_t specializedKey);

// The variant `spirv` with `specConstants` on this device, as the index knows it.
std::uint64_t variantKey(const VkPhysicalDeviceProperties& device, const std::uint32_t* spirv, std::size_t spirvBytes,
                         const std::vector<std::uint32_t>& specConstants);

// The index of the variants compiled on this machine: a file of keys under
// $XDG_CACHE_HOME/vkrt (~/.cache/vkrt), one per driver shader cache (MESA_SHADER_CACHE_DIR),
// none when that cache is disabled (MESA_SHADER_CACHE_DISABLE). A missing or unwritable
// index only costs compiles: every error is ignored.
std::string variantIndexPath();
bool variantCompiled(std::uint64_t key);
void recordVariantCompiled(std::uint64_t key);

}  // namespace vkrt
