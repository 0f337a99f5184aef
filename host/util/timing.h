// Stage timing for --stats.
#pragma once

#include <chrono>

namespace vkrt {

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace vkrt
