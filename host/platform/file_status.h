// What a path names on the file system, on any system: its kind, size, identity ("the same
// file"), number of names, permission bits and owner. Depends on nothing but the C++ library.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace vkrt::platform {

enum class FileKind { Regular, Directory, CharacterDevice, BlockDevice, Fifo, Socket, SymbolicLink, Other };

// What "the same file" means: POSIX's st_dev and st_ino; Windows' volume serial number and
// file index, taken from an open handle (mingw's stat gives st_ino 0 for every file).
struct FileIdentity {
  std::uint64_t volume = 0, file = 0;
  friend bool operator==(const FileIdentity&, const FileIdentity&) = default;
};

struct FileStatus {
  int error = 0;            // 0: the file is there; otherwise the errno value saying why not
                            // (ENOENT, ENOTDIR, EACCES, ELOOP...), and the fields below are 0
  FileKind kind = FileKind::Other;
  std::uint64_t size = 0;   // bytes, for a regular file
  FileIdentity identity{};
  std::uint64_t links = 0;  // its names (hard links)
  unsigned mode = 0;        // permission bits, 07777 (Windows: 0444 or 0666 by the read-only
                            // attribute, 0555 or 0777 for a folder)
  unsigned uid = 0, gid = 0;   // its owner (0 on Windows)

  bool found() const { return error == 0; }
  bool is(FileKind k) const { return found() && kind == k; }
};

// The status of the file `path` names, through symbolic links (stat).
FileStatus statusOf(const std::string& path);
// The same, but a symbolic link at the end of `path` is itself described (lstat).
FileStatus linkStatusOf(const std::string& path);
// The status of an open file (fstat), by its descriptor or its stream.
FileStatus statusOfOpen(int fd);
FileStatus statusOfOpen(std::FILE* stream);

// Whether `path` names a regular file (through links): not a folder, FIFO, device or socket.
bool isRegularFile(const std::string& path);
// Whether `path` names a folder (through links).
bool isDirectory(const std::string& path);

}  // namespace vkrt::platform
