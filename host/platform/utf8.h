// Text between vkrt (UTF-8 in std::string, everywhere) and Windows' wide-character
// interfaces (UTF-16). Windows only.
#pragma once

#ifdef _WIN32
#  include <string>

namespace vkrt::platform {

// UTF-16 for Windows' *W functions; invalid UTF-8 becomes U+FFFD.
std::wstring wideFromUtf8(const std::string& text);
// UTF-8 of what a *W function gave.
std::string utf8FromWide(const std::wstring& text);

}  // namespace vkrt::platform
#endif
