// Win32 error codes as errno values, for the Windows half of the platform layer: its file
// functions fail as the POSIX calls they stand for (errno set), so that callers build one
// message on every system. Windows only; nothing outside host/platform/ uses it.
#pragma once

#ifdef _WIN32
namespace vkrt::platform {

// A Win32 error (GetLastError()) as the errno value the POSIX call would have set:
// ERROR_FILE_NOT_FOUND -> ENOENT, ERROR_ACCESS_DENIED -> EACCES, a sharing or lock violation
// -> EBUSY; EIO for what has no counterpart.
int errnoFromWin32(unsigned long win32Error);

// Sets errno from GetLastError() and returns -1.
int failWithLastError();

}  // namespace vkrt::platform
#endif
