// What kind of image a file is, from its first bytes or its name (host/cli/image_argument.h).
#include "cli/image_argument.h"

#include <cstring>
#include <fstream>

#include "image/image_file.h"
#include "platform/file_status.h"

namespace vkrt {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::optional<std::string> imageKind(const std::string& path) {
  if (platform::isRegularFile(path)) {
    std::ifstream in(path, std::ios::binary);
    char head[8] = {};
    if (in.read(head, sizeof head) || in.gcount() > 0) {
      const std::size_t n = static_cast<std::size_t>(in.gcount());
      for (const ImageFormat& format : imageFormats())
        if (format.isFile(path)) return std::string(format.name);
      // Kinds vkrt reads (stb_image) and does not write.
      if (n >= 3 && std::memcmp(head, "\xFF\xD8\xFF", 3) == 0) return "JPEG";
      if (n >= 3 && head[0] == 'P' && head[1] == '3' && blank(head[2])) return "PPM";   // ASCII
      return std::nullopt;   // read, and not an image: a scene, or the parser says what is wrong
    }
  }
  return imageKindByName(path);
}

}  // namespace vkrt
