// Stop requests on Windows: the console's control handler (signals.h).
#define WIN32_LEAN_AND_MEAN
#define NOMINMAX
#include <windows.h>

#include <string>

#include "platform/signals.h"
#include "platform/utf8.h"

namespace vkrt::platform {
namespace {

void (*handler)(int) = nullptr;

BOOL WINAPI onConsoleEvent(DWORD event) {
  switch (event) {
    case CTRL_C_EVENT:
    case CTRL_BREAK_EVENT:
      handler(kSignalInterrupt);
      return TRUE;
    case CTRL_CLOSE_EVENT:
    case CTRL_LOGOFF_EVENT:
    case CTRL_SHUTDOWN_EVENT:
      // Windows ends the process when this returns (5 s after a close at the latest): give the
      // main thread the time to stop, remove its temporary file and exit by itself.
      handler(kSignalHangUp);
      ::Sleep(4000);
      return TRUE;
    default:
      return FALSE;
  }
}

}  // namespace

void onStopRequests(void (*onRequest)(int number)) {
  handler = onRequest;
  ::SetConsoleCtrlHandler(onConsoleEvent, TRUE);
}

// (The console handler is a thread of its own, not a signal: converting the name is safe.)
void removeFileNow(const char* path) { ::DeleteFileW(wideFromUtf8(path).c_str()); }

void exitNow(int status) { ::ExitProcess(static_cast<UINT>(status)); }

}  // namespace vkrt::platform
