// Libraries opened at run time on POSIX: dlopen (library.h).
#include "platform/library.h"

#include <cstddef>

#include <dlfcn.h>
#if defined(VKRT_SANITIZE_BUILD) && defined(__linux__)
#  include <link.h>
#endif

namespace vkrt::platform {

#ifdef __APPLE__
const char* vulkanLoaderName() { return "libvulkan.1.dylib"; }   // MoltenVK's loader (untested)
#else
const char* vulkanLoaderName() { return "libvulkan.so.1"; }
#endif

void* openVulkanLoader() {
  void* lib = ::dlopen(vulkanLoaderName(), RTLD_NOW | RTLD_LOCAL);
#ifndef __APPLE__
  if (!lib) lib = ::dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
#endif
  return lib;
}

void* librarySymbol(void* library, const char* name) { return ::dlsym(library, name); }

void pinLoadedLibraries() {
#if defined(VKRT_SANITIZE_BUILD) && defined(__linux__)
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        if (info->dlpi_name && info->dlpi_name[0] != '\0') dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
#endif
}

}  // namespace vkrt::platform
