// The page of `vkrt view`: view_page.h. The page itself is host/cli/view_page.html, embedded
// by the build. Element ids its script and the tests read: image (data-version: the image
// shown), phase, round, samples, seconds, progress, warnings, error, check, plot, connection.
#include "cli/view_page.h"

#include "view_page.html.h"   // kViewPage: host/cli/view_page.html, embedded by the build

namespace vkrt {

std::string_view viewPage() { return {reinterpret_cast<const char*>(kViewPage), kViewPageSize}; }

}  // namespace vkrt
