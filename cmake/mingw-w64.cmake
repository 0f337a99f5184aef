# Cross-compiling vkrt.exe for 64-bit Windows with Debian's mingw-w64 (the POSIX-threads
# variant: std::thread and std::mutex). `bash .ci/install-deps --windows` installs the compiler
# and makes the Windows builds of the libraries (.ci/mingw-deps) in VKRT_MINGW_PREFIX.
#
#   cmake -S . -B build-windows --toolchain cmake/mingw-w64.cmake
#   cmake --build build-windows --target vkrt
#
# The shaders compile on the build machine (its glslangValidator and spirv-opt), as on Linux.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
if(DEFINED ENV{VKRT_MINGW_PREFIX})
  set(VKRT_MINGW_PREFIX "$ENV{VKRT_MINGW_PREFIX}" CACHE PATH "The Windows builds of vkrt's libraries (.ci/mingw-deps)")
else()
  set(VKRT_MINGW_PREFIX /var/cache/vkrt-ci/mingw-w64 CACHE PATH "The Windows builds of vkrt's libraries (.ci/mingw-deps)")
endif()
# Libraries, headers and CMake packages from the mingw-w64 sysroot and the prefix only;
# programs (glslangValidator, spirv-opt, gzip, Python) from the build machine.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${VKRT_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# zlib's static library (its import library would need zlib1.dll beside vkrt.exe).
set(ZLIB_USE_STATIC_LIBS ON)
# The tests run vkrt.exe and the test programs under Wine (.ci/windows).
find_program(VKRT_WINE wine)
if(VKRT_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${VKRT_WINE})
endif()
