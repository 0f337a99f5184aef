// Between vkrt's file names (UTF-8 text in std::string, everywhere) and std::filesystem::path,
// on any system. Depends on nothing but the C++ library.
//
// Why not std::filesystem::path(text) and path.string(): on Windows a path holds UTF-16, and
// libstdc++ (mingw) widens a std::string byte by byte, as Latin-1, whatever the process's code
// page, while path.string() gives UTF-8; a round trip turns each non-ASCII letter into two or
// more (U+03A9, bytes CE A9, into U+00CE U+00A9). On POSIX a path holds the bytes as they
// are, and these two are that.
#pragma once

#include <filesystem>
#include <string>

namespace vkrt::platform {

// The characters that end a folder's name in a path: the slash (POSIX, where a backslash may
// be part of a name), the slash and the backslash (Windows).
#ifdef _WIN32
inline constexpr const char* kPathSeparators = "/\\";
#else
inline constexpr const char* kPathSeparators = "/";
#endif

// The path that the UTF-8 name `text` stands for. On Windows invalid UTF-8 becomes U+FFFD,
// as for every other file function of this layer (utf8.h), so both name the same file.
std::filesystem::path pathFromUtf8(const std::string& text);

// The UTF-8 name of `path`, as vkrt's messages, options and file functions take it. On
// Windows a lone surrogate (a name no UTF-8 can spell) becomes U+FFFD.
std::string utf8FromPath(const std::filesystem::path& path);

}  // namespace vkrt::platform
