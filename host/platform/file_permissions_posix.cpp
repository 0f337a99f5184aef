// Permission bits and owners on POSIX (file_permissions.h).
#include "platform/file_permissions.h"

#include <sys/stat.h>
#include <unistd.h>

namespace vkrt::platform {

int setMode(const std::string& path, unsigned mode) { return ::chmod(path.c_str(), static_cast<mode_t>(mode)); }

int setOpenMode(int fd, unsigned mode) { return ::fchmod(fd, static_cast<mode_t>(mode)); }

int setOpenOwner(int fd, unsigned uid, unsigned gid) {
  return ::fchown(fd, static_cast<uid_t>(uid), static_cast<gid_t>(gid));
}

bool changesOwners() { return ::geteuid() == 0; }

unsigned creationMask() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<unsigned>(mask);
}

bool isWritable(const std::string& path) { return ::access(path.c_str(), W_OK) == 0; }

}  // namespace vkrt::platform
