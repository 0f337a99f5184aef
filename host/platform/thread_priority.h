// Lowering the priority of the calling thread alone: vkrt view's server yields the CPU to
// the render it shows.
#pragma once

namespace vkrt::platform {

// The calling thread runs below the process's other threads: nice +10 on Linux (setpriority
// of its thread id); THREAD_PRIORITY_BELOW_NORMAL on Windows; nothing where the system sets
// no priority per thread (macOS here). A failure leaves it as it was.
void lowerThisThreadsPriority();

}  // namespace vkrt::platform
