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
  std::vector<Buffer> dropped;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    dropped.swap(kept_);
    kept_ = std::move(buffers);
  }
}   // `dropped` freed outside the lock

void BufferPool::retainSizes(const std::vector<std::size_t>& sizes) {
  std::vector<Buffer> dropped;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Buffer> retained;
    for (Buffer& b : kept_)
      (std::find(sizes.begin(), sizes.end(), b.size()) != sizes.end() ? retained : dropped).push_back(std::move(b));
    kept_ = std::move(retained);
  }
}

std::size_t BufferPool::kept() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return kept_.size();
}

}  // namespace vkrt
