// Terminal progress bar.
#include "render/progress.h"

#include <cstdio>

#include "platform/terminal.h"

namespace vkrt {

ProgressBar::ProgressBar(bool enabled)
    : active_(enabled && platform::isTerminal(stderr)), start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

void ProgressBar::update(std::uint64_t done, std::uint64_t total, const std::string& note) {
  if (!active_ || total == 0) return;
  std::lock_guard lock(mutex_);
  auto now = std::chrono::steady_clock::now();
  if (done < total && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  double fraction = static_cast<double>(done) / static_cast<double>(total);
  double elapsed = std::chrono::duration<double>(now - start_).count();
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  int filled = static_cast<int>(fraction * kWidth);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : ' ';
  bar[kWidth] = '\0';
  if (fraction > 0.0 && done < total)
    std::fprintf(stderr, "\r[%s] %3d%%  ETA %.1f s  %s ", bar, static_cast<int>(fraction * 100.0),
                 elapsed * (1.0 - fraction) / fraction, note.c_str());
  else
    std::fprintf(stderr, "\r[%s] %3d%%  %.1f s  %s     ", bar, static_cast<int>(fraction * 100.0), elapsed,
                 note.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

}  // namespace vkrt
