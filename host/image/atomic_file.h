// Writing a file whole or not at all (temporary file beside the target, then rename), for
// every image format, and the one place that decides what an output path names on the file
// system. Depends on nothing but errors.h, interrupt.h, byte_sink.h and the platform layer's
// file functions.
//
// What writing an output does to the user's files:
//  - a symbolic link is followed (through every link) and its target replaced; the link
//    stays a link;
//  - only a regular file is replaced, keeping its permission bits (and, for root, its owner
//    and group); a directory, device, FIFO or socket is refused (IoError), never opened;
//  - a file with several names (hard links) is refused: renaming a new file over one name
//    would leave the others with the old image;
//  - an existing file that this user may not write is refused, as a plain create would be.
#pragma once

#include <functional>
#include <string>

#include "image/byte_sink.h"
#include "platform/file_status.h"

namespace vkrt {

// An output path resolved: the file that writing it creates or replaces.
struct OutputFile {
  std::string target;      // `path`, or where its symbolic links lead
  std::string canonical;   // target as an absolute path without links, '.' or '..': one name per file
  bool exists = false;     // then the fields below are the existing file's
  platform::FileIdentity identity{};
  unsigned mode = 0;       // permission bits (07777)
  unsigned uid = 0, gid = 0;
};

// Resolves `path` for writing, or throws IoError saying why it cannot be written: a folder
// on the way that does not exist or is a file, a directory, device, FIFO or socket at the
// end, several hard links, a loop of symbolic links, a file named as a scene (*.test, any
// case). Creates nothing.
OutputFile resolveOutputFile(const std::string& path);

// Throws IoError unless `path` can be created or replaced (resolveOutputFile, and the
// directory of its target is writable, and an existing file too).
void checkOutputWritable(const std::string& path);

// Calls `write` with a FileSink (image/byte_sink.h; its errors name `path`) over a temporary
// file beside the target of `path` (named .vkrt-XXXXXX`suffix`), then renames it over the
// target, so an existing file is replaced whole or not at all. Throws IoError (and whatever
// `write` throws, e.g. Interrupted); no temporary file is left behind. A signal caught by
// interrupt.h's handlers (SIGINT, SIGTERM, SIGHUP) stops the write before the rename: the
// temporary file is removed.
void writeFileAtomic(const std::string& path, const char* suffix, const std::function<void(ByteSink& file)>& write);

}  // namespace vkrt
