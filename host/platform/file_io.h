// Reading and writing open files, on any system. A file is a descriptor: POSIX's, or on
// Windows the C runtime's, always opened in binary mode (without _O_BINARY Windows turns CRLF
// into LF and stops reading at a byte 0x1A). Each function fails as the POSIX call it stands
// for: -1 with errno set. Depends on nothing but the C++ library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace vkrt::platform {

// `path` opened for reading (open(O_RDONLY | O_CLOEXEC)); a folder opens on POSIX, and on
// Windows fails with EISDIR.
int openForReading(const std::string& path);

// `path` opened for appending, created with permission bits `mode` (less the umask) when it
// is not there; never through a symbolic link at the end (O_NOFOLLOW: the open fails).
int openForAppending(const std::string& path, unsigned mode);

// Up to `size` bytes read (read): the count, 0 at the end, -1 with errno set (EINTR: a signal).
std::int64_t readSome(int fd, void* data, std::size_t size);
// The same at `offset`, the file's position left alone (pread).
std::int64_t readSomeAt(int fd, void* data, std::size_t size, std::uint64_t offset);
// Up to `size` bytes written (write): the count or -1 with errno set.
std::int64_t writeSome(int fd, const void* data, std::size_t size);
// The same at `offset`, the file's position left alone (pwrite).
std::int64_t writeSomeAt(int fd, const void* data, std::size_t size, std::uint64_t offset);

// The file's data on the disk (fsync; Windows: _commit, FlushFileBuffers): 0 or -1.
int syncFile(int fd);
// Closes `fd`: 0 or -1.
int closeFile(int fd);

}  // namespace vkrt::platform
