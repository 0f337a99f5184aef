// Who may do what with a file, on any system: permission bits, owners, the umask. On Windows
// a file's permission bits are its read-only attribute (no 0200 bit: read-only) and owners are
// not changed. Each function fails as the POSIX call it stands for: -1 (or false) with errno
// set. Depends on nothing but the C++ library.
#pragma once

#include <string>

namespace vkrt::platform {

// Sets the permission bits of `path` (chmod) or of an open file (fchmod): 0 or -1.
int setMode(const std::string& path, unsigned mode);
int setOpenMode(int fd, unsigned mode);

// Gives an open file an owner and group (fchown; Windows: nothing): 0 or -1.
int setOpenOwner(int fd, unsigned uid, unsigned gid);

// Whether this process may give files to other users (effective user root; never on Windows).
bool changesOwners();

// The permission bits that a new file does not get (the umask), read without changing it.
unsigned creationMask();

// Whether this user may write the existing file `path` (access(W_OK)); false with errno set.
bool isWritable(const std::string& path);

}  // namespace vkrt::platform
