// Making, replacing and removing files on POSIX (file_changes.h).
#include "platform/file_changes.h"

#include <cstdio>
#include <cstdlib>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vkrt::platform {

int createTemporaryFile(std::string& pattern, std::size_t suffixLength) {
  return ::mkstemps(pattern.data(), static_cast<int>(suffixLength));
}

bool createTemporaryDirectory(std::string& pattern) { return ::mkdtemp(pattern.data()) != nullptr; }

int makeDirectory(const std::string& path, unsigned mode) { return ::mkdir(path.c_str(), static_cast<mode_t>(mode)); }

int replaceFile(const std::string& from, const std::string& to) { return std::rename(from.c_str(), to.c_str()); }

int removeFile(const std::string& path) { return ::unlink(path.c_str()); }

}  // namespace vkrt::platform
