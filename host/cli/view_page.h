// The page `vkrt view` serves (cli/web_view.h): one HTML document with its style and script
// inline, nothing fetched from elsewhere. Its script reads the token from its own address,
// follows /events (the state as JSON: cli/web_view.cpp, stateJson) and shows /image.png
// each time the image changes, loading the new one before it replaces the old.
#pragma once

#include <string_view>

namespace vkrt {

std::string_view viewPage();

}  // namespace vkrt
