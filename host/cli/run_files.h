// The files one run of vkrt reads and writes, checked against each other before anything is
// rendered or written: an output is never a file the run reads (a scene, the --check
// reference, diff's images, merge's tiles) nor another output of the run. Files are told
// apart by what they are (their identity: device and inode, or Windows' volume and file
// index; or the canonical path of a file not yet there), not by how they are spelt: './a.png', a symbolic link to it, a hard link and a
// path through a linked folder are all a.png.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "platform/file_status.h"
#include "util/errors.h"

namespace vkrt {

// An output refused because it is a file of the run: a usage error (exit 1), printed
// without the usage text (the command line's syntax is fine).
class RefusedOutput : public UsageError {
 public:
  using UsageError::UsageError;
};

class RunFiles {
 public:
  // A file this run reads, and what it is in messages ("the scene file", "the reference
  // image (--check)"). One that does not exist is remembered by its canonical path.
  void addInput(const std::string& path, const std::string& role);
  // Throws RefusedOutput when `path` (resolved as atomic_file.h's resolveOutputFile does,
  // which throws IoError for a path that cannot be written) is an input or an output
  // added before; else returns.
  void checkOutput(const std::string& path, const std::string& role) const;
  // checkOutput, then remembers `path` as an output of the run.
  void addOutput(const std::string& path, const std::string& role);

  // A file as the run knows it. Two are the same when both exist and share their identity
  // (one file, whatever its names: a hard link, a link's target), or else by their
  // canonical names.
  struct File {
    std::string path, role, canonical;
    bool exists = false;
    platform::FileIdentity identity{};
  };
  static bool same(const File& a, const File& b);

 private:
  // `path` as it is now: the identity of what is there, else its canonical name.
  static File fileNamed(const std::string& path, const std::string& role);
  File resolvedOutput(const std::string& path, const std::string& role) const;
  std::vector<File> inputs_, outputs_;
};

}  // namespace vkrt
