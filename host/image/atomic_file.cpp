// Atomic file writing: mkstemps beside the target, fsync, rename. Ctrl-C between the two
// leaves the old file (the temporary file is registered with host/util/interrupt.h, which
// removes it on a second signal). resolveOutputFile decides, before anything is written,
// which file a path names and whether vkrt may replace it (atomic_file.h).
#include "image/atomic_file.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/errors.h"
#include "image/image_file.h"
#include "util/interrupt.h"
#include "util/text.h"   // abbreviated

namespace vkrt {
namespace {

std::string directoryOf(const std::string& path) {
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// What a file that is not a regular one is, for messages ("a FIFO").
const char* kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}

// The text of the symbolic link `path`.
std::string readLink(const std::string& path, const std::string& name) {
  std::string buf(PATH_MAX, '\0');
  ssize_t n = ::readlink(path.c_str(), buf.data(), buf.size());
  if (n < 0) throw IoError("cannot write '" + name + "': cannot read the symbolic link '" + abbreviated(path) +
                           "': " + std::strerror(errno));
  buf.resize(static_cast<std::size_t>(n));
  return buf;
}

// The folder `dir` must exist and be a folder; says which part of it is not.
void checkDirectory(const std::string& dir, const std::string& name) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      throw IoError("output directory '" + abbreviated(dir) + "' is not a directory: it is " +
                    (S_ISREG(st.st_mode) ? std::string("a regular file") : kindOf(st.st_mode)) + " (output '" +
                    name + "')");
    return;
  }
  const int error = errno;
  if (error == ENOTDIR) {   // a file on the way: name the first one
    std::filesystem::path prefix;
    for (const auto& part : std::filesystem::path(dir)) {
      prefix /= part;
      if (::stat(prefix.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw IoError("output directory '" + abbreviated(dir) + "' cannot exist: '" + abbreviated(prefix.string()) +
                      "' is " + (S_ISREG(st.st_mode) ? std::string("a regular file") : kindOf(st.st_mode)) +
                      ", not a directory");
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
  struct stat st {};
  int hops = 0;
  for (;; ++hops) {
    if (::lstat(out.target.c_str(), &st) != 0) {
      if (errno == ENOENT || errno == ENOTDIR) break;   // a new file (its folder is checked below)
      throw IoError("cannot write '" + name + "': " + std::strerror(errno));
    }
    if (!S_ISLNK(st.st_mode)) {
      out.exists = true;
      break;
    }
    if (hops == 40) throw IoError("cannot write '" + name + "': " + std::strerror(ELOOP));
    std::string link = readLink(out.target, name);
    out.target = link.front() == '/' ? link : (std::filesystem::path(directoryOf(out.target)) / link).string();
  }
  const std::string described =
      "'" + name + "'" + (hops > 0 ? " (a symbolic link to '" + abbreviated(out.target) + "')" : std::string());
  // A link whose text names no file, though the system follows it (/dev/stdout, /proc/self/fd/N).
  struct stat followed {};
  if (!out.exists && hops > 0 && ::stat(path.c_str(), &followed) == 0) {
    if (!S_ISREG(followed.st_mode))
      throw IoError("cannot write " + described + ": it is " + kindOf(followed.st_mode) +
                    "; vkrt writes images only into regular files");
    throw IoError("cannot write " + described + ": the link leads to a file that has no name vkrt can replace; "
                  "give the file's own name");
  }
  std::string file = std::filesystem::path(out.target).filename().string();
  if (file.empty() || file == "." || file == "..")
    throw IoError("output path " + described + " names a directory, not a file");
  // vkrt's outputs are images and reports, never scenes: an output named as a scene file is
  // a slip (arguments swapped, a scene named for another), and would replace a scene.
  if (namedAsSceneFile(file))
    throw IoError("cannot write " + described + ": that is a scene file's name (.test), and vkrt writes images, "
                  "never scenes; name the output as what it holds (" +
                  std::filesystem::path(file).replace_extension(".png").string() + ")");
  const std::string dir = directoryOf(out.target);
  checkDirectory(dir, name);
  if (out.exists) {
    if (S_ISDIR(st.st_mode)) throw IoError("output path " + described + " is a directory");
    if (!S_ISREG(st.st_mode))
      throw IoError("cannot write " + described + ": it is " + kindOf(st.st_mode) +
                    "; vkrt writes images only into regular files, and never replaces anything else");
    if (st.st_nlink > 1)
      throw IoError("cannot replace " + described + ": it has " + std::to_string(st.st_nlink) +
                    " names (hard links), and vkrt writes a new file and renames it over the old one, which "
                    "would leave the other names with the old image; remove the other links or write elsewhere");
    out.device = static_cast<std::uint64_t>(st.st_dev);
    out.inode = static_cast<std::uint64_t>(st.st_ino);
    out.mode = static_cast<unsigned>(st.st_mode & 07777);
    out.uid = static_cast<unsigned>(st.st_uid);
    out.gid = static_cast<unsigned>(st.st_gid);
  }
  std::unique_ptr<char, decltype(&std::free)> real(::realpath(dir.c_str(), nullptr), &std::free);
  if (!real) throw IoError("output directory '" + abbreviated(dir) + "': " + std::strerror(errno));
  out.canonical = (std::filesystem::path(real.get()) / file).string();
  return out;
}

void writeAll(int fd, const std::uint8_t* data, std::size_t size, const std::string& path) {
  while (size > 0) {
    ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError("cannot write '" + abbreviated(path) + "': " + std::strerror(errno));
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

void writeAllAt(int fd, const std::uint8_t* data, std::size_t size, std::uint64_t offset, const std::string& path) {
  while (size > 0) {
    ssize_t n = ::pwrite(fd, data, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw IoError("cannot write '" + path + "': " + (n < 0 ? std::strerror(errno) : "no progress"));
    data += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
}

void checkOutputWritable(const std::string& path) {
  OutputFile out = resolveOutputFile(path);
  if (out.exists && ::access(out.target.c_str(), W_OK) != 0)
    throw IoError("output file '" + abbreviated(out.target) + "' is not writable: " + std::strerror(errno));
  // Creating a file is the only reliable test (permissions, read-only mounts, root).
  std::string dir = directoryOf(out.target);
  std::string probe = (std::filesystem::path(dir) / ".vkrt-XXXXXX.probe").string();
  int fd = ::mkstemps(probe.data(), 6);
  if (fd < 0)
    throw IoError("output directory '" + abbreviated(dir) + "' is not writable: " + std::strerror(errno));
  registerTemporaryFile(probe.c_str());
  ::close(fd);
  ::unlink(probe.c_str());
  registerTemporaryFile(nullptr);
}

void writeFileAtomic(const std::string& path, const char* suffix, const std::function<void(int fd)>& write) {
  const OutputFile out = resolveOutputFile(path);
  const std::string name = abbreviated(path);
  const std::string dir = directoryOf(out.target);
  std::string tmpl = (std::filesystem::path(dir) / (std::string(".vkrt-XXXXXX") + suffix)).string();
  int fd = ::mkstemps(tmpl.data(), static_cast<int>(std::strlen(suffix)));
  if (fd < 0) throw IoError("cannot create a temporary file in '" + abbreviated(dir) + "': " + std::strerror(errno));
  registerTemporaryFile(tmpl.c_str());
  try {
    if (out.exists) {
      // The new file takes the old one's place: its permissions, and for root its owner
      // (chown first: it clears the set-user-ID bits that chmod then restores).
      if (::geteuid() == 0 && ::fchown(fd, static_cast<uid_t>(out.uid), static_cast<gid_t>(out.gid)) != 0)
        throw IoError("cannot write '" + name + "': cannot give the new file the old one's owner: " +
                      std::strerror(errno));
      if (::fchmod(fd, static_cast<mode_t>(out.mode)) != 0)
        throw IoError("cannot write '" + name + "': cannot give the new file the old one's permissions: " +
                      std::strerror(errno));
    } else {
      // The permissions a plain create would give it (mkstemp makes it 0600).
      mode_t mask = ::umask(0);
      ::umask(mask);
      ::fchmod(fd, 0666 & ~mask);
    }
    waitForSignalIfTesting("write");
    write(fd);
    if (::fsync(fd) != 0 && errno != EINVAL) throw IoError("cannot write '" + name + "': " + std::strerror(errno));
    int closed = ::close(fd);
    fd = -1;
    if (closed != 0) throw IoError("cannot write '" + name + "': " + std::strerror(errno));
    throwIfInterrupted();   // the last moment at which the old file is still there
    if (::rename(tmpl.c_str(), out.target.c_str()) != 0)
      throw IoError("cannot write '" + name + "': " + std::strerror(errno));
  } catch (...) {
    if (fd >= 0) ::close(fd);
    ::unlink(tmpl.c_str());
    registerTemporaryFile(nullptr);
    throw;
  }
  registerTemporaryFile(nullptr);
}

}  // namespace vkrt
