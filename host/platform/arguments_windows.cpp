// The command line on Windows: the wide one, as UTF-8 (arguments.h).
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <windows.h>
#include <shellapi.h>

#include "platform/arguments.h"
#include "platform/utf8.h"

namespace vkrt::platform {

std::vector<std::string> commandLineArguments(int argc, char** argv) {
  ::SetConsoleOutputCP(CP_UTF8);
  int count = 0;
  LPWSTR* wide = ::CommandLineToArgvW(::GetCommandLineW(), &count);
  if (!wide) return std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + argc);
  std::vector<std::string> out;
  for (int i = 1; i < count; ++i) out.push_back(utf8FromWide(wide[i]));
  ::LocalFree(wide);
  return out;
}

}  // namespace vkrt::platform
