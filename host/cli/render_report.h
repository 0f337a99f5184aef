// What a render reports: its --stats breakdown and its samples on stderr, the warning for its
// NaN or infinite pixels, its figures as JSON (--compare --json). Renders nothing.
#pragma once

#include <string>

#include "render/render.h"

namespace vkrt {

// " (N samples)" after a path integrator's output, with "time up" when --time ended it, and
// how far past it the first batch ran when that alone took longer.
std::string samplesNote(const RenderReport& r);

// --stats: the scene, each stage's time and the rays, on stderr.
void printStats(const RenderRequest& req, const RenderReport& r);

// The times and rays of one render as a JSON object.
std::string reportJson(const RenderReport& r);

// The warning for pixels whose colour was NaN or infinite (with --strict: an error already);
// under --compare, which writes nothing, named by the backend that rendered them.
void warnNonFinite(bool quiet, const RenderReport& report, const std::string& backend = "");

}  // namespace vkrt
