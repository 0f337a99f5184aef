// The console on Windows (terminal.h).
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <io.h>
#include <windows.h>

#include "platform/terminal.h"

namespace vkrt::platform {

bool isTerminal(std::FILE* stream) {
  if (!::_isatty(::_fileno(stream))) return false;
  HANDLE console = reinterpret_cast<HANDLE>(::_get_osfhandle(::_fileno(stream)));
  DWORD mode = 0;
  if (!::GetConsoleMode(console, &mode)) return false;
  // Windows 10 and later draw escape sequences once asked to; without them, no bar.
  return (mode & ENABLE_VIRTUAL_TERMINAL_PROCESSING) != 0 ||
         ::SetConsoleMode(console, mode | ENABLE_VIRTUAL_TERMINAL_PROCESSING) != 0;
}

void prepareStandardStreams() { std::setvbuf(stderr, nullptr, _IONBF, 0); }

}  // namespace vkrt::platform
