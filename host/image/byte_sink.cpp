// The two destinations of image bytes (byte_sink.h): an open file, written until all of it
// is there (a write may take part of it, or be cut short by a signal), and a string.
#include "image/byte_sink.h"

#include <cerrno>
#include <cstring>
#include <limits>
#include <new>

#include "platform/file_io.h"
#include "util/errors.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

void FileSink::write(const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const std::int64_t n = platform::writeSome(fd_, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError("cannot write '" + abbreviated(path_) + "': " + std::strerror(errno));
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

void FileSink::writeAt(const std::uint8_t* data, std::size_t size, std::uint64_t offset) {
  while (size > 0) {
    const std::int64_t n = platform::writeSomeAt(fd_, data, size, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw IoError("cannot write '" + path_ + "': " + (n < 0 ? std::strerror(errno) : "no progress"));
    data += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
}

void MemorySink::write(const std::uint8_t* data, std::size_t size) {
  writeAt(data, size, position_);
  position_ += size;
}

void MemorySink::writeAt(const std::uint8_t* data, std::size_t size, std::uint64_t offset) {
  if (size == 0) return;
  if (offset > std::numeric_limits<std::size_t>::max() - size) throw std::bad_alloc();
  const auto at = static_cast<std::size_t>(offset);
  if (at + size > bytes_.size()) bytes_.resize(at + size);   // zeros between the end and `at`
  std::memcpy(bytes_.data() + at, data, size);
}

}  // namespace vkrt
