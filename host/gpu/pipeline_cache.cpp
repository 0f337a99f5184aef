// The pipelines a context keeps.
#include "gpu/pipeline_cache.h"

namespace vkrt {

PipelineCache::~PipelineCache() {
  for (auto& [key, p] : pipelines_) {
    vk::vkDestroyPipeline(device_, p.pipeline, nullptr);
    vk::vkDestroyPipelineLayout(device_, p.layout, nullptr);
    vk::vkDestroyDescriptorSetLayout(device_, p.setLayout, nullptr);
  }
}

const CompiledPipeline& PipelineCache::get(const PipelineKey& key, const std::function<CompiledPipeline()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) return it->second;
  return pipelines_.emplace(key, make()).first->second;
}

std::size_t PipelineCache::made() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return pipelines_.size();
}

}  // namespace vkrt
