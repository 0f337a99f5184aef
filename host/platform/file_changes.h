// Making, replacing and removing files and folders, on any system. Each function fails as the
// POSIX call it stands for: -1 (or false) with errno set. Depends on nothing but the C++ library.
#pragma once

#include <cstddef>
#include <string>

namespace vkrt::platform {

// A new file, made for this user alone (0600) and opened for reading and writing, its name
// `pattern` with the six 'X' that come `suffixLength` bytes before its end replaced by
// letters and digits no file there has (mkstemps; Windows: an exclusive create, retried with
// another name while one is taken). Returns the descriptor (binary, not inherited) and
// leaves the name made in `pattern`; -1 with errno set.
int createTemporaryFile(std::string& pattern, std::size_t suffixLength);

// A new folder, for this user alone, `pattern` ending in six 'X' made a name no file there
// has (mkdtemp). Returns false with errno set.
bool createTemporaryDirectory(std::string& pattern);

// A folder (mkdir) with permission bits `mode` less the umask: 0 or -1.
int makeDirectory(const std::string& path, unsigned mode);

// Puts the file or folder `from` in the place of `to` at once, replacing a file `to` (rename;
// Windows: MoveFileExW, written through to the disk). Windows refuses while another program
// (an image viewer) holds `to` open: the move is tried again for about two seconds, then fails
// with EBUSY, which errorText (error_text.h) words as such. 0 or -1.
int replaceFile(const std::string& from, const std::string& to);

// Removes the file `path` (unlink): 0 or -1.
int removeFile(const std::string& path);

}  // namespace vkrt::platform
