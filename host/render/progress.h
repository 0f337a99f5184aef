// Progress bar on stderr: percentage and ETA, redrawn at most 10 times a second, and only
// when stderr is a terminal. Thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace vkrt {

class ProgressBar {
 public:
  // Draws only when `enabled` and stderr is a terminal.
  explicit ProgressBar(bool enabled);
  // `note`, when given, follows the ETA (a progressive render's "12/64 samples").
  void update(std::uint64_t done, std::uint64_t total, const std::string& note = {});
  // Clears the bar's line.
  void finish();

 private:
  bool active_;
  bool drawn_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace vkrt
