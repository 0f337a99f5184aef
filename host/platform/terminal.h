// The terminal: whether a stream goes to one (progress bars are drawn only there).
#pragma once

#include <cstdio>

namespace vkrt::platform {

// Whether `stream` (stdout or stderr) writes to a terminal or console that shows the escape
// sequences vkrt draws with ("\r", "\033[K"). Windows: a console, whose escape processing
// this turns on.
bool isTerminal(std::FILE* stream);

// Makes stderr behave as on Linux wherever it goes: unbuffered, each message out as it is
// printed (Windows' C library buffers stderr when it is a pipe or a file, so a program
// reading vkrt's messages, --watch's lines among them, saw them only at its exit). Call it
// first thing in main().
void prepareStandardStreams();

}  // namespace vkrt::platform
