// Atomic file writing: a temporary file beside the target, fsync, rename (host/platform/'s
// file functions). Ctrl-C between the two leaves the old file (the temporary file is
// registered with host/util/interrupt.h, which removes it on a second signal).
// resolveOutputFile decides, before anything is written, which file a path names and whether
// vkrt may replace it (atomic_file.h).
#include "image/atomic_file.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/errors.h"
#include "image/image_file.h"
#include "platform/error_text.h"
#include "platform/file_changes.h"
#include "platform/file_io.h"
#include "platform/file_names.h"
#include "platform/file_permissions.h"
#include "platform/file_status.h"
#include "platform/path_text.h"
#include "util/interrupt.h"
#include "util/text.h"   // abbreviated

namespace vkrt {
namespace {

using platform::FileKind;
using platform::FileStatus;
using platform::pathFromUtf8;
using platform::utf8FromPath;

std::string directoryOf(const std::string& path) {
  std::filesystem::path parent = pathFromUtf8(path).parent_path();
  return parent.empty() ? std::string(".") : utf8FromPath(parent);
}

// What a file that is not a regular one is, for messages ("a FIFO").
const char* kindOf(FileKind kind) {
  switch (kind) {
    case FileKind::Directory: return "a directory";
    case FileKind::CharacterDevice: return "a character device";
    case FileKind::BlockDevice: return "a block device";
    case FileKind::Fifo: return "a FIFO (named pipe)";
    case FileKind::Socket: return "a socket";
    case FileKind::SymbolicLink: return "a symbolic link";
    case FileKind::Regular:
    case FileKind::Other: break;
  }
  return "not a regular file";
}

// What a file is, for messages ("a regular file", "a FIFO (named pipe)").
std::string whatItIs(FileKind kind) {
  return kind == FileKind::Regular ? std::string("a regular file") : kindOf(kind);
}

// The text of the symbolic link `path`.
std::string readLink(const std::string& path, const std::string& name) {
  std::optional<std::string> text = platform::readSymbolicLink(path);
  if (!text) throw IoError("cannot write '" + name + "': cannot read the symbolic link '" + abbreviated(path) +
                           "': " + std::strerror(errno));
  return *text;
}

// The folder `dir` must exist and be a folder; says which part of it is not.
void checkDirectory(const std::string& dir, const std::string& name) {
  const FileStatus st = platform::statusOf(dir);
  if (st.found()) {
    if (st.kind != FileKind::Directory)
      throw IoError("output directory '" + abbreviated(dir) + "' is not a directory: it is " + whatItIs(st.kind) +
                    " (output '" + name + "')");
    return;
  }
  const int error = st.error;
  // A file on the way: name the first one. (Windows says ENOENT where POSIX says ENOTDIR;
  // where POSIX says ENOENT, every folder on the way that is there is a folder.)
  if (error == ENOTDIR || error == ENOENT) {
    std::filesystem::path prefix;
    for (const auto& part : pathFromUtf8(dir)) {
      prefix /= part;
      const std::string soFar = utf8FromPath(prefix);
      const FileStatus on = platform::statusOf(soFar);
      if (on.found() && on.kind != FileKind::Directory)
        throw IoError("output directory '" + abbreviated(dir) + "' cannot exist: '" + abbreviated(soFar) +
                      "' is " + whatItIs(on.kind) + ", not a directory");
    }
  }
  if (error == ENOENT || error == ENOTDIR) throw IoError("output directory '" + abbreviated(dir) + "' does not exist");
  throw IoError("output directory '" + abbreviated(dir) + "': " + std::strerror(error));
}

}  // namespace

OutputFile resolveOutputFile(const std::string& path) {
  if (path.empty()) throw IoError("output path is empty");
  const std::string name = abbreviated(path);
  OutputFile out;
  out.target = path;
  // Follow the symbolic links at the end of the path: the file written is where they lead.
  FileStatus st;
  int hops = 0;
  for (;; ++hops) {
    st = platform::linkStatusOf(out.target);
    if (!st.found()) {
      if (st.error == ENOENT || st.error == ENOTDIR) break;   // a new file (its folder is checked below)
      throw IoError("cannot write '" + name + "': " + std::strerror(st.error));
    }
    if (st.kind != FileKind::SymbolicLink) {
      out.exists = true;
      break;
    }
    if (hops == 40) throw IoError("cannot write '" + name + "': " + std::strerror(ELOOP));
    std::string link = readLink(out.target, name);
    const std::filesystem::path to = pathFromUtf8(link);
    out.target = to.has_root_path() ? link : utf8FromPath(pathFromUtf8(directoryOf(out.target)) / to);
  }
  const std::string described =
      "'" + name + "'" + (hops > 0 ? " (a symbolic link to '" + abbreviated(out.target) + "')" : std::string());
  // A link whose text names no file, though the system follows it (/dev/stdout, /proc/self/fd/N).
  if (!out.exists && hops > 0)
    if (const FileStatus followed = platform::statusOf(path); followed.found()) {
      if (followed.kind != FileKind::Regular)
        throw IoError("cannot write " + described + ": it is " + kindOf(followed.kind) +
                      "; vkrt writes images only into regular files");
      throw IoError("cannot write " + described + ": the link leads to a file that has no name vkrt can replace; "
                    "give the file's own name");
    }
  std::string file = utf8FromPath(pathFromUtf8(out.target).filename());
  if (file.empty() || file == "." || file == "..")
    throw IoError("output path " + described + " names a directory, not a file");
  // vkrt's outputs are images and reports, never scenes: an output named as a scene file is
  // a slip (arguments swapped, a scene named for another), and would replace a scene.
  if (namedAsSceneFile(file))
    throw IoError("cannot write " + described + ": that is a scene file's name (.test), and vkrt writes images, "
                  "never scenes; name the output as what it holds (" +
                  utf8FromPath(pathFromUtf8(file).replace_extension(".png")) + ")");
  const std::string dir = directoryOf(out.target);
  checkDirectory(dir, name);
  if (out.exists) {
    if (st.kind == FileKind::Directory) throw IoError("output path " + described + " is a directory");
    if (st.kind != FileKind::Regular)
      throw IoError("cannot write " + described + ": it is " + kindOf(st.kind) +
                    "; vkrt writes images only into regular files, and never replaces anything else");
    if (st.links > 1)
      throw IoError("cannot replace " + described + ": it has " + std::to_string(st.links) +
                    " names (hard links), and vkrt writes a new file and renames it over the old one, which "
                    "would leave the other names with the old image; remove the other links or write elsewhere");
    out.identity = st.identity;
    out.mode = st.mode & 07777;
    out.uid = st.uid;
    out.gid = st.gid;
  }
  const std::optional<std::string> real = platform::realPath(dir);
  if (!real) throw IoError("output directory '" + abbreviated(dir) + "': " + std::strerror(errno));
  out.canonical = utf8FromPath(pathFromUtf8(*real) / pathFromUtf8(file));
  return out;
}

void checkOutputWritable(const std::string& path) {
  OutputFile out = resolveOutputFile(path);
  if (out.exists && !platform::isWritable(out.target))
    throw IoError("output file '" + abbreviated(out.target) + "' is not writable: " + std::strerror(errno));
  // Creating a file is the only reliable test (permissions, read-only mounts, root).
  std::string dir = directoryOf(out.target);
  std::string probe = utf8FromPath(pathFromUtf8(dir) / ".vkrt-XXXXXX.probe");
  const int fd = platform::createTemporaryFile(probe, 6);
  if (fd < 0)
    throw IoError("output directory '" + abbreviated(dir) + "' is not writable: " + std::strerror(errno));
  registerTemporaryFile(probe.c_str());
  platform::closeFile(fd);
  platform::removeFile(probe);
  registerTemporaryFile(nullptr);
}

void writeFileAtomic(const std::string& path, const char* suffix, const std::function<void(ByteSink& file)>& write) {
  const OutputFile out = resolveOutputFile(path);
  const std::string name = abbreviated(path);
  const std::string dir = directoryOf(out.target);
  std::string tmpl = utf8FromPath(pathFromUtf8(dir) / (std::string(".vkrt-XXXXXX") + suffix));
  int fd = platform::createTemporaryFile(tmpl, std::strlen(suffix));
  if (fd < 0) throw IoError("cannot create a temporary file in '" + abbreviated(dir) + "': " + std::strerror(errno));
  registerTemporaryFile(tmpl.c_str());
  try {
    if (out.exists) {
      // The new file takes the old one's place: its permissions, and for root its owner
      // (chown first: it clears the set-user-ID bits that chmod then restores).
      if (platform::changesOwners() && platform::setOpenOwner(fd, out.uid, out.gid) != 0)
        throw IoError("cannot write '" + name + "': cannot give the new file the old one's owner: " +
                      std::strerror(errno));
      if (platform::setOpenMode(fd, out.mode) != 0)
        throw IoError("cannot write '" + name + "': cannot give the new file the old one's permissions: " +
                      std::strerror(errno));
    } else {
      // The permissions a plain create would give it (mkstemp makes it 0600).
      platform::setOpenMode(fd, 0666 & ~platform::creationMask());
    }
    waitForSignalIfTesting("write");
    FileSink file(fd, path);
    write(file);
    if (platform::syncFile(fd) != 0 && errno != EINVAL) throw IoError("cannot write '" + name + "': " + std::strerror(errno));
    const int closed = platform::closeFile(fd);
    fd = -1;
    if (closed != 0) throw IoError("cannot write '" + name + "': " + std::strerror(errno));
    throwIfInterrupted();   // the last moment at which the old file is still there
    if (platform::replaceFile(tmpl, out.target) != 0)
      throw IoError("cannot write '" + name + "': " + platform::errorText(errno));
  } catch (...) {
    if (fd >= 0) platform::closeFile(fd);
    platform::removeFile(tmpl);
    registerTemporaryFile(nullptr);
    throw;
  }
  registerTemporaryFile(nullptr);
}

}  // namespace vkrt
