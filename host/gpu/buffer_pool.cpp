#include "gpu/buffer_pool.h"

#include <algorithm>
#include <utility>

namespace vkrt {

Buffer BufferPool::take(const Context& context, std::size_t bytes) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = kept_.begin(); it != kept_.end(); ++it) {
      if (it->size() != bytes) continue;
      Buffer b(std::move(*it));
      kept_.erase(it);
      return b;
    }
  }
  return Buffer(context, bytes);
}

void BufferPool::keep(std::vector<Buffer> buffers) {
  std::size_t total = 0;
  for (const Buffer& b : buffers) total += b.size();
  std::vector<Buffer> dropped;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    dropped.swap(kept_);
    if (total <= maxBytes_) kept_ = std::move(buffers);
  }
}   // `dropped` (and `buffers` when too large) freed outside the lock

void BufferPool::retainSizes(const std::vector<std::size_t>& sizes) {
  std::vector<Buffer> dropped;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::size_t> wanted = sizes;
    std::vector<Buffer> retained;
    for (Buffer& b : kept_) {
      const auto it = std::find(wanted.begin(), wanted.end(), b.size());
      const bool taken = it != wanted.end();
      if (taken) wanted.erase(it);
      (taken ? retained : dropped).push_back(std::move(b));
    }
    kept_ = std::move(retained);
  }
}

std::size_t BufferPool::kept() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return kept_.size();
}

}  // namespace vkrt
