// The compiled compute pipelines a Vulkan context keeps for the renders that follow: a scene
// rendered again (vkrt --watch after an edit, a batch of scenes of the same features) takes
// the VkPipeline of the first render, whose shader the driver compiled then (lavapipe compiles
// at pipeline creation and again, for its JIT, at the first dispatch: bench/README.md, "Latest
// figures: first render, shader variants, responsiveness"), instead of compiling it again. A
// pipeline is known by its SPIR-V, its binding
// types, its specialization constants and its push-constant size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "gpu/vulkan_api.h"

namespace vkrt {

// The parts of a pipeline that depend on its shader and layout alone (every render binds its
// own buffers through its own descriptor set).
struct CompiledPipeline {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

struct PipelineKey {
  const std::uint32_t* spirv = nullptr;   // the shader's embedded SPIR-V (static storage)
  std::size_t spirvBytes = 0;
  std::vector<VkDescriptorType> bindingTypes;
  std::vector<std::uint32_t> specConstants;
  std::uint32_t pushConstantBytes = 0;
  bool operator<(const PipelineKey& o) const {
    return std::tie(spirv, spirvBytes, bindingTypes, specConstants, pushConstantBytes) <
           std::tie(o.spirv, o.spirvBytes, o.bindingTypes, o.specConstants, o.pushConstantBytes);
  }
};

class PipelineCache {
 public:
  explicit PipelineCache(VkDevice device) : device_(device) {}
  ~PipelineCache();   // destroys every pipeline (before the device is)
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // The pipeline of `key`: the one kept, or made now by `make` (which creates all three
  // handles, or destroys what it made and throws) and kept.
  // A second caller of the same key (or another) waits while one is made: a pipeline made
  // ahead on another thread (ComputePipeline::prepare) is then taken when it is done.
  const CompiledPipeline& get(const PipelineKey& key, const std::function<CompiledPipeline()>& make);
  // How many pipelines `make` has made.
  std::size_t made() const;

 private:
  VkDevice device_;
  mutable std::mutex mutex_;
  std::map<PipelineKey, CompiledPipeline> pipelines_;
};

}  // namespace vkrt
