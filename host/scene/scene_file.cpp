#include "scene/scene_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "platform/file_io.h"
#include "platform/file_status.h"
#include "util/errors.h"
#include "util/interrupt.h"
#include "scene/diagnostic.h"
#include "scene/tokenizer.h"

namespace vkrt {
namespace {

// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) platform::closeFile(fd);
  }
};

SceneError readLimitError(const std::string& path, int line, std::string message) {
  return SceneError({{path, line, std::move(message) + "; is this a scene file?", Severity::Error}});
}

}  // namespace

// The text of the scene file `path`, read with read(2) (in binary: a CRLF file's text keeps its
// CRs, which the tokenizer takes as blanks) in chunks of at most a mebibyte:
//  - a signal that interrupts an open or a read (Ctrl-C while a FIFO waits for its writer)
//    ends it as Interrupted (interrupt.h), where vkrt's handler caught it; any other
//    interruption is retried;
//  - reading stops at the first byte that is not text, kept as the last byte, so that the
//    tokenizer says where it is (a device like /dev/zero: at once);
//  - a line longer than kMaxSceneLineBytes, or a file longer than kMaxSceneFileBytes, is a
//    SceneError at that line, found as soon as the bytes past the limit are read (a regular
//    file's size is checked before reading).
std::string readSceneText(const std::string& path) {
  const std::string name = abbreviated(path);
  FileDescriptor file;
  while ((file.fd = platform::openForReading(path)) < 0) {
    if (errno != EINTR) throw IoError("cannot open scene file '" + name + "': " + std::strerror(errno));
    throwIfInterrupted();
  }
  const platform::FileStatus st = platform::statusOfOpen(file.fd);
  if (!st.found()) throw IoError("cannot read scene file '" + name + "': " + std::strerror(st.error));
  if (st.is(platform::FileKind::Directory))
    throw IoError("cannot read scene file '" + name + "': " + std::strerror(EISDIR));
  std::string text;
  if (st.is(platform::FileKind::Regular)) {
    if (st.size > kMaxSceneFileBytes)
      throw readLimitError(path, 0,
                           "the file is " + std::to_string(st.size) + " bytes, more than the " +
                               std::to_string(kMaxSceneFileBytes) + " (1 GiB) a scene file may hold");
    text.reserve(static_cast<std::size_t>(st.size));   // one buffer of its size: no regrowth, no copies
  }
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::size_t scanned = 0, lineStart = 0;
  int line = 1;
  char probe[1 << 16];   // the read that finds the end of a buffer filled to its reserved size
  for (;;) {
    throwIfInterrupted();
    const std::size_t size = text.size();
    const std::size_t room = std::min(text.capacity() - size, kChunk);
    std::int64_t n = 0;
    int readError = 0;
    if (room > 0) {
      text.resize(size + room);
      n = platform::readSome(file.fd, text.data() + size, room);
      readError = errno;
      text.resize(size + static_cast<std::size_t>(std::max<std::int64_t>(n, 0)));
    } else {
      n = platform::readSome(file.fd, probe, sizeof probe);
      readError = errno;
      if (n > 0) {
        // A stream (or a file that grew): grow by doubling, never much past the limit.
        std::size_t want = std::max(text.capacity() * 2, size + kChunk);
        text.reserve(std::min(want, kMaxSceneFileBytes + kChunk));
        text.append(probe, static_cast<std::size_t>(n));
      }
    }
    if (n < 0) {
      if (readError == EINTR) continue;   // the loop's first line ends it when a signal asked to stop
      throw IoError("cannot read scene file '" + name + "': " + std::strerror(readError));
    }
    if (n == 0) break;
    // Up to the first byte past the file's limit, whose line is then the one reported.
    const std::size_t end = std::min(text.size(), kMaxSceneFileBytes);
    bool longLine = false;
    for (; scanned < end; ++scanned) {
      const char c = text[scanned];
      if (c == '\n') {
        if ((longLine = scanned - lineStart > kMaxSceneLineBytes)) break;
        ++line;
        lineStart = scanned + 1;
      } else if (!isTextByte(c)) {
        text.resize(scanned + 1);   // the parser reports it
        return text;
      }
    }
    if (longLine || scanned - lineStart > kMaxSceneLineBytes)
      throw readLimitError(path, line,
                           "the line is longer than " + std::to_string(kMaxSceneLineBytes) +
                               " bytes (1 MiB), the most a line of a scene file may hold");
    if (text.size() > kMaxSceneFileBytes)
      throw readLimitError(path, line,
                           "the file goes on past " + std::to_string(kMaxSceneFileBytes) +
                               " bytes (1 GiB), the most a scene file may hold");
  }
  return text;
}

}  // namespace vkrt
