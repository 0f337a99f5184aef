// PNG writing with stb_image_write, reading with stb_image.
#include "image/png.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>

#include <zlib.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

// stb_image_write's own deflate is slow; zlib at level 1 writes the same pixels about 3x
// faster (the files are a little larger).
unsigned char* vkrtZlibCompress(unsigned char* data, int length, int* outLength, int quality);
#define STBIW_ZLIB_COMPRESS vkrtZlibCompress
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

unsigned char* vkrtZlibCompress(unsigned char* data, int length, int* outLength, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));   // stb frees it with STBIW_FREE (free)
  if (!out) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(length), 1) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *outLength = static_cast<int>(size);
  return out;
}

namespace vkrt {
namespace {

std::string directoryOf(const std::string& path) {
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

struct WriteState {
  int fd;
  bool failed = false;
  int error = 0;
};

void writeToFd(void* context, void* data, int size) {
  auto* st = static_cast<WriteState*>(context);
  const char* p = static_cast<const char*>(data);
  std::size_t left = static_cast<std::size_t>(size);
  while (!st->failed && left > 0) {
    ssize_t n = ::write(st->fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      st->failed = true;
      st->error = errno;
      return;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

}  // namespace

void checkOutputWritable(const std::string& path) {
  if (path.empty()) throw IoError("output path is empty");
  std::string dir = directoryOf(path);
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw IoError("output directory '" + dir + "' does not exist");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw IoError("output path '" + path + "' is a directory");
  // Creating a file is the only reliable test (permissions, read-only mounts, root).
  std::string probe = (std::filesystem::path(dir) / ".vkrt-XXXXXX.probe").string();
  int fd = ::mkstemps(probe.data(), 6);
  if (fd < 0) throw IoError("output directory '" + dir + "' is not writable: " + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void writePngAtomic(const Image& image, const std::string& path) {
  std::string tmpl = (std::filesystem::path(directoryOf(path)) / ".vkrt-XXXXXX.png.tmp").string();
  int fd = ::mkstemps(tmpl.data(), 8);
  if (fd < 0) throw IoError("cannot create a temporary file in '" + directoryOf(path) + "': " + std::strerror(errno));
  WriteState st{fd};
  int ok = stbi_write_png_to_func(writeToFd, &st, image.width, image.height, 3, image.rgb.data(), image.width * 3);
  // The file gets the permissions a plain create would give it (mkstemp makes it 0600).
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  if (!ok && !st.failed) {
    st.failed = true;
    st.error = ENOMEM;
  }
  if (!st.failed && ::fsync(fd) != 0 && errno != EINVAL) {
    st.failed = true;
    st.error = errno;
  }
  if (::close(fd) != 0 && !st.failed) {
    st.failed = true;
    st.error = errno;
  }
  if (!st.failed && ::rename(tmpl.c_str(), path.c_str()) != 0) {
    st.failed = true;
    st.error = errno;
  }
  if (st.failed) {
    ::unlink(tmpl.c_str());
    throw IoError("cannot write '" + path + "': " + std::strerror(st.error));
  }
}

Image readImage(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) throw IoError("cannot read image '" + path + "': " + stbi_failure_reason());
  Image img(w, h);
  std::memcpy(img.rgb.data(), data, img.rgb.size());
  stbi_image_free(data);
  return img;
}

}  // namespace vkrt
