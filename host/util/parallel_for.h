// One small parallel loop for every layer that shares work out over the cores: the CPU
// reference's tiles (cpu/pixel_tiles) and `vkrt grade`'s comparisons (cli/grade).
#pragma once

#include <cstddef>
#include <functional>

namespace vkrt {

// Runs job(i) for each i in [0, count) on `threads` threads (0: one a core; the caller's
// thread among them; never more than count), each taking the next index when it finishes
// one. Once `stop` (may be empty; asked before each index) answers true, or a job throws, no
// further index is handed out; after every thread has finished, the first exception thrown is
// rethrown here.
void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job,
                 const std::function<bool()>& stop = {});

}  // namespace vkrt
