// The checks of grade_guard.h.
#include "grade/grade_guard.h"

#include "image/image_file.h"
#include "platform/error_text.h"
#include "platform/file_status.h"
#include "util/errors.h"
#include "util/text.h"   // abbreviated

namespace vkrt {

namespace {

const char* kindName(platform::FileKind kind) {
  switch (kind) {
    case platform::FileKind::Directory: return "a folder";
    case platform::FileKind::CharacterDevice:
    case platform::FileKind::BlockDevice: return "a device";
    case platform::FileKind::Fifo: return "a FIFO";
    case platform::FileKind::Socket: return "a socket";
    default: return "not a regular file";
  }
}

// Why `path` is not read as a file of at most `most` bytes, or "".
std::string fileProblem(const std::string& path, std::uint64_t most, const char* what) {
  const platform::FileStatus st = platform::statusOf(path);
  const std::string name = "'" + abbreviated(path) + "'";
  if (!st.found()) return name + " cannot be read (" + platform::errorText(st.error) + "); not read";
  if (!st.is(platform::FileKind::Regular))
    return name + " is " + kindName(st.kind) + ", not a regular file; not read";
  if (st.size > most)
    return name + " is " + std::to_string(st.size >> 20) + " MB, longer than " + what + " can be (" +
           std::to_string(most >> 20) + " MB); not read";
  return "";
}

}  // namespace

std::uint64_t maxSubmittedImageBytes(int width, int height) {
  return (std::uint64_t{64} << 20) + 16 * static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
}

SubmittedImage checkSubmittedImage(const std::string& path, int referenceWidth, int referenceHeight) {
  SubmittedImage s;
  s.problem = fileProblem(path, maxSubmittedImageBytes(referenceWidth, referenceHeight),
                          "an image of the reference's size");
  if (!s.problem.empty()) return s;
  try {
    if (isFloatImageFile(path)) {
      const RadianceImage info = readFloatImageInfo(path);
      s.width = info.width, s.height = info.height;
    } else {
      readImageSize(path, s.width, s.height);
    }
  } catch (const IoError& e) {
    s.problem = e.what();
  }
  return s;
}

std::string submittedSceneProblem(const std::string& path) {
  return fileProblem(path, kMaxSubmittedSceneBytes, "a scene file handed in");
}

}  // namespace vkrt
