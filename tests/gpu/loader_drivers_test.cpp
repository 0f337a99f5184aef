// The drivers vkrt asks the Vulkan loader to skip (gpu/loader_drivers.h): those that reach GPUs
// only through DRM render nodes, on a machine without one; never a user's own choice.
#include <algorithm>
#include <filesystem>
#include <map>
#include <system_error>

#include <gtest/gtest.h>

#include "gpu/loader_drivers.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

std::vector<std::pair<std::string, std::string>> settingsWith(const std::map<std::string, std::string>& env,
                                                              bool hasRenderNode) {
  return loaderDriverSettings(
      [&](const char* name) {
        auto it = env.find(name);
        return it == env.end() ? static_cast<const char*>(nullptr) : it->second.c_str();
      },
      hasRenderNode);
}

bool hasSetting(const std::vector<std::pair<std::string, std::string>>& settings, const std::string& name) {
  for (const auto& s : settings)
    if (s.first == name) return true;
  return false;
}

// The manifests in `dir` that vkrt asks the loader to skip without a render node: those whose
// names match one of VK_LOADER_DRIVERS_DISABLE's globs (each a prefix and '*', as vkrt writes
// them). Debian 12 names Mesa's manifests intel_icd.x86_64.json, Debian 13 intel_icd.json.
std::vector<std::string> installedSkippedManifests(const std::filesystem::path& dir) {
  const std::string globs = settingsWith({}, false).at(0).second;
  std::vector<std::string> found;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    for (std::size_t start = 0; start <= globs.size();) {
      std::size_t comma = globs.find(',', start);
      if (comma == std::string::npos) comma = globs.size();
      std::string glob = globs.substr(start, comma - start);
      if (!glob.empty() && glob.back() == '*') glob.pop_back();
      if (name.rfind(glob, 0) == 0) {
        found.push_back(name);
        break;
      }
      start = comma + 1;
    }
  }
  return found;
}

}  // namespace

TEST(LoaderDrivers, WithoutARenderNodeTheGpuDriversAreSkipped) {
  auto settings = settingsWith({}, false);
  ASSERT_EQ(settings.size(), 2u);
  EXPECT_EQ(settings[0].first, "VK_LOADER_DRIVERS_DISABLE");
  for (const char* driver : {"intel_icd*", "intel_hasvk_icd*", "radeon_icd*"})
    EXPECT_NE(settings[0].second.find(driver), std::string::npos) << driver;
  for (const char* kept : {"lvp", "nvidia", "swiftshader"})   // drivers that need no render node
    EXPECT_EQ(settings[0].second.find(kept), std::string::npos) << kept;
  EXPECT_EQ(settings[1], std::make_pair(std::string("VK_LOADER_LAYERS_DISABLE"), std::string("VK_LAYER_MESA_device_select")));
}

// Mesa's manifests as Debian 12 names them (intel_icd.x86_64.json) and as Debian 13 does
// (intel_icd.json, and gfxstream_vk_icd.json for virtio GPUs): the render-node drivers of both
// are found to be skipped, and lavapipe is not.
TEST(LoaderDrivers, BothReleasesManifestNamesAreRecognised) {
  const std::string dir = freshDir("loader-manifests");
  for (const char* name : {"intel_icd.x86_64.json", "radeon_icd.x86_64.json", "intel_hasvk_icd.x86_64.json",
                           "lvp_icd.x86_64.json", "intel_icd.json", "radeon_icd.json", "intel_hasvk_icd.json",
                           "gfxstream_vk_icd.json", "lvp_icd.json", "nvidia_icd.json"})
    writeFile(dir + "/" + name, "{}");
  std::vector<std::string> found = installedSkippedManifests(dir);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, (std::vector<std::string>{"gfxstream_vk_icd.json", "intel_hasvk_icd.json", "intel_hasvk_icd.x86_64.json",
                                            "intel_icd.json", "intel_icd.x86_64.json", "radeon_icd.json",
                                            "radeon_icd.x86_64.json"}));
}

TEST(LoaderDrivers, WithARenderNodeNothingIsSkipped) { EXPECT_TRUE(settingsWith({}, true).empty()); }

TEST(LoaderDrivers, TheUsersChoiceStands) {
  for (const char* drivers : {"VK_ICD_FILENAMES", "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES", "VK_LOADER_DRIVERS_SELECT",
                              "VK_LOADER_DRIVERS_DISABLE"}) {
    auto settings = settingsWith({{drivers, "x"}}, false);
    EXPECT_FALSE(hasSetting(settings, "VK_LOADER_DRIVERS_DISABLE")) << drivers;
    EXPECT_TRUE(hasSetting(settings, "VK_LOADER_LAYERS_DISABLE")) << drivers;
  }
  for (const char* layers : {"VK_LOADER_LAYERS_ENABLE", "VK_LOADER_LAYERS_DISABLE", "VK_INSTANCE_LAYERS",
                             "MESA_VK_DEVICE_SELECT"}) {
    auto settings = settingsWith({{layers, "x"}}, false);
    EXPECT_TRUE(hasSetting(settings, "VK_LOADER_DRIVERS_DISABLE")) << layers;
    EXPECT_FALSE(hasSetting(settings, "VK_LOADER_LAYERS_DISABLE")) << layers;
  }
}

// The loader's own search for drivers and layers, whatever the environment the tests run in
// sets (VK_DRIVER_FILES, as vkrt's "no Vulkan driver" message tells users to set): `env`'s
// words that leave out every variable that chooses them.
const std::string kLoadersOwnSearch =
    "-u VK_ICD_FILENAMES -u VK_DRIVER_FILES -u VK_ADD_DRIVER_FILES -u VK_LOADER_DRIVERS_SELECT "
    "-u VK_LOADER_DRIVERS_DISABLE -u VK_LOADER_LAYERS_ENABLE -u VK_LOADER_LAYERS_DISABLE -u VK_LOADER_LAYERS_ALLOW "
    "-u VK_INSTANCE_LAYERS -u MESA_VK_DEVICE_SELECT -u NODEVICE_SELECT";

// The binary on this machine: without a render node, the loader's own log says an installed
// Intel or Radeon driver was skipped at vkrt's request, and the devices listed are those the
// loader lists with every driver (a user's VK_LOADER_DRIVERS_SELECT, obeyed as given). The
// loader searches on its own here (kLoadersOwnSearch): a chosen driver skips nothing.
TEST(LoaderDrivers, TheBinarySkipsThemAndFindsTheSameDevices) {
  if (hasDrmRenderNode()) GTEST_SKIP() << "this machine has a DRM render node: nothing is skipped here";
  const bool installed = !installedSkippedManifests("/usr/share/vulkan/icd.d").empty();
  if (!installed) VKRT_SKIP_UNLESS_CI("no Mesa Intel or Radeon Vulkan driver installed to be skipped");
  if (!installed) return;
  RunResult logged = runVkrt("--list-devices", kLoadersOwnSearch + " VK_LOADER_DEBUG=driver");
  EXPECT_EQ(logged.exitCode, 0) << logged.output;
  EXPECT_NE(logged.output.find("disabled by env var 'VK_LOADER_DRIVERS_DISABLE'"), std::string::npos) << logged.output;
  RunResult skipped = runVkrt("--list-devices", kLoadersOwnSearch);
  RunResult every = runVkrt("--list-devices", kLoadersOwnSearch + " VK_LOADER_DRIVERS_SELECT='*'");
  EXPECT_EQ(skipped.exitCode, 0) << skipped.output;
  EXPECT_EQ(skipped.output, every.output);
  RunResult chosen = runVkrt("--list-devices", kLoadersOwnSearch + " VK_LOADER_DEBUG=driver VK_LOADER_DRIVERS_SELECT='*'");
  EXPECT_EQ(chosen.output.find("VK_LOADER_DRIVERS_DISABLE"), std::string::npos) << chosen.output;
}
