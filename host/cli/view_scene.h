// vkrt view SCENE: the watch loop (cli/watch.h) with its page served (cli/web_view.h,
// net/http_server.h): the page's address, with a fresh token, is the first line on stdout.
#pragma once

#include "cli/options.h"

namespace vkrt {

// Returns as watchScene does. Throws IoError (the address cannot be listened on, the
// reference cannot be read), and what watchScene throws.
int viewScene(RenderOptions& options);

}  // namespace vkrt
