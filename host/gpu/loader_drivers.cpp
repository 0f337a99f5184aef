// The Vulkan loader's drivers: loader_drivers.h.
#include "gpu/loader_drivers.h"

#include <cstdlib>

#include "platform/process.h"

namespace vkrt {
namespace {

// The drivers that reach their GPUs through DRM render nodes only, by their manifests' file
// names (the loader's globs): Mesa's for Intel, Radeon, Nouveau, virtio, Apple, Qualcomm,
// Arm, Broadcom and Imagination GPUs, AMD's own, and gfxstream's (virtual GPUs of emulators,
// in Debian 13's Mesa; without a render node it loads and finds nothing). Debian 12 names the
// manifests intel_icd.x86_64.json, Debian 13 intel_icd.json: the globs match both.
constexpr const char* kRenderNodeDrivers =
    "intel_icd*,intel_hasvk_icd*,radeon_icd*,nouveau_icd*,virtio_icd*,asahi_icd*,freedreno_icd*,panfrost_icd*,"
    "broadcom_icd*,powervr_mesa_icd*,amd_icd*,gfxstream_vk_icd*";
constexpr const char* kDeviceSelectLayer = "VK_LAYER_MESA_device_select";

// The loader's variables that choose drivers, and those that choose layers (or the device
// the device-select layer puts first): any of them set means the user chose.
constexpr const char* kDriverChoices[] = {"VK_ICD_FILENAMES", "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES",
                                          "VK_LOADER_DRIVERS_SELECT", "VK_LOADER_DRIVERS_DISABLE"};
constexpr const char* kLayerChoices[] = {"VK_LOADER_LAYERS_ENABLE", "VK_LOADER_LAYERS_DISABLE",
                                         "VK_LOADER_LAYERS_ALLOW", "VK_INSTANCE_LAYERS",
                                         "MESA_VK_DEVICE_SELECT", "NODEVICE_SELECT"};

}  // namespace

std::vector<std::pair<std::string, std::string>> loaderDriverSettings(
    const std::function<const char*(const char*)>& lookup, bool hasRenderNode) {
  std::vector<std::pair<std::string, std::string>> out;
  if (hasRenderNode) return out;
  auto anySet = [&](const auto& names) {
    for (const char* name : names)
      if (lookup(name)) return true;
    return false;
  };
  if (!anySet(kDriverChoices)) out.emplace_back("VK_LOADER_DRIVERS_DISABLE", kRenderNodeDrivers);
  if (!anySet(kLayerChoices)) out.emplace_back("VK_LOADER_LAYERS_DISABLE", kDeviceSelectLayer);
  return out;
}

bool hasDrmRenderNode() { return platform::hasDrmRenderNode(); }

void skipDriversWithoutDevices() {
  for (const auto& [name, value] :
       loaderDriverSettings([](const char* name) { return static_cast<const char*>(std::getenv(name)); }, hasDrmRenderNode()))
    platform::setEnvironmentDefault(name, value);
}

}  // namespace vkrt
