// The status of a file: what every system shares (file_status.h).
#include "platform/file_status.h"

namespace vkrt::platform {

bool isRegularFile(const std::string& path) { return statusOf(path).is(FileKind::Regular); }

bool isDirectory(const std::string& path) { return statusOf(path).is(FileKind::Directory); }

}  // namespace vkrt::platform
