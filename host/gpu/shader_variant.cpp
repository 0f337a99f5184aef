// The choice of a shader variant and the index of those compiled.
#include "gpu/shader_variant.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>
#include <string_view>

#include "platform/file_changes.h"
#include "platform/file_io.h"
#include "platform/path_text.h"
#include "platform/process.h"

namespace vkrt {
namespace {

// FNV-1a, 64 bits.
struct Hash {
  std::uint64_t h = 14695981039346656037ull;
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  void add(std::string_view s) { add(s.data(), s.size()); }
};

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

std::mutex indexMutex;

// The keys of the index at `path`, read once (again when the path changes: another cache).
std::set<std::uint64_t>& keys(const std::string& path) {
  static std::set<std::uint64_t> set;
  static std::string readFrom;
  static bool read = false;
  if (read && readFrom == path) return set;
  read = true;
  readFrom = path;
  set.clear();
  if (path.empty()) return set;
  if (FILE* f = std::fopen(path.c_str(), "r")) {
    unsigned long long k = 0;
    while (std::fscanf(f, "%llx", &k) == 1) set.insert(k);
    std::fclose(f);
  }
  return set;
}

}  // namespace

bool specializationPays(bool cpuDevice, double estimatedRays, bool pathShader) {
  if (!cpuDevice) return estimatedRays > kSpecializeGpuAboveRays;
  return estimatedRays > (pathShader ? kSpecializePathAboveRays : kSpecializeWhittedAboveRays);
}

bool autoTakesSpecialised(bool cpuDevice, double estimatedRays, bool pathShader, std::uint64_t specializedKey) {
  return specializationPays(cpuDevice, estimatedRays, pathShader) || (cpuDevice && variantCompiled(specializedKey));
}

std::uint64_t variantKey(const VkPhysicalDeviceProperties& device, const std::uint32_t* spirv, std::size_t spirvBytes,
                         const std::vector<std::uint32_t>& specConstants) {
  Hash h;
  h.add(device.pipelineCacheUUID, sizeof device.pipelineCacheUUID);
  h.add(&device.driverVersion, sizeof device.driverVersion);
  h.add(spirv, spirvBytes);
  h.add(specConstants.data(), specConstants.size() * sizeof(std::uint32_t));
  return h.h;
}

std::string variantIndexPath() {
  const std::string disabled = env("MESA_SHADER_CACHE_DISABLE");
  if (disabled == "1" || disabled == "true" || disabled == "TRUE" || disabled == "yes") return "";
  const std::string home = platform::userCacheFolder();
  if (home.empty()) return "";
  std::string mesa = env("MESA_SHADER_CACHE_DIR");
  if (mesa.empty()) mesa = home + "/mesa_shader_cache";
  Hash h;
  h.add(mesa);
  char name[64];
  std::snprintf(name, sizeof name, "/vkrt/compiled-variants-%016llx", static_cast<unsigned long long>(h.h));
  return home + name;
}

bool variantCompiled(std::uint64_t key) {
  std::lock_guard lock(indexMutex);
  return keys(variantIndexPath()).count(key) > 0;
}

void recordVariantCompiled(std::uint64_t key) {
  std::lock_guard lock(indexMutex);
  const std::string path = variantIndexPath();
  if (path.empty() || !keys(path).insert(key).second) return;
  platform::makeDirectory(platform::utf8FromPath(platform::pathFromUtf8(path).parent_path()), 0755);
  // One short line by one append: whole even when processes add at once. O_NOFOLLOW: never
  // through a link.
  const int fd = platform::openForAppending(path, 0644);
  if (fd < 0) return;
  char line[32];
  const int n = std::snprintf(line, sizeof line, "%016llx\n", static_cast<unsigned long long>(key));
  if (platform::writeSome(fd, line, static_cast<std::size_t>(n)) != n) {
    // (a full disk: the variant is compiled again next time)
  }
  platform::closeFile(fd);
}

}  // namespace vkrt
