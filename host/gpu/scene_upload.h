// The scene's arrays in device buffers, and the descriptor bindings of a shader that reads
// them (gpu_types.h, kBinding*): what raytrace.comp and pathtrace.comp read alike.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/vulkan_settings.h"
#include "scene/flatten.h"

namespace vkrt {

// A shader's bindings 0..N-1: a buffer and a descriptor type each.
struct ShaderBindings {
  explicit ShaderBindings(std::uint32_t count)
      : types(count, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER), buffers(count, nullptr) {}
  void set(std::uint32_t binding, const Buffer& buffer, VkDescriptorType type) {
    buffers[binding] = &buffer;
    types[binding] = type;
  }
  // Binds each buffer at its binding, as its type says: a uniform texel buffer as a view of
  // uints (the primitive references) or of uvec4 texels (the rest).
  void bindTo(ComputePipeline& pipeline) const;
  std::vector<VkDescriptorType> types;
  std::vector<const Buffer*> buffers;
};

// Which arrays a shader reads: the Whitted shader's (triangles .. primitive references), or
// the path shader's (also quad lights and emitters).
enum class SceneArrays { Whitted, Path };

class SceneUpload {
 public:
  SceneUpload(const Context& context, const GpuScene& scene, SceneArrays arrays);
  ~SceneUpload();   // gives the arrays' buffers to the context's pool, for the next upload
  SceneUpload(const SceneUpload&) = delete;
  SceneUpload& operator=(const SceneUpload&) = delete;
  // Whether every array read through a texel view fits `maxTexels` texels.
  bool texelsFit(std::size_t maxTexels) const;
  // Sets the scene's bindings: uniform texel buffers with `texelReads`, else storage buffers
  // (the emitters are a storage buffer either way).
  void bind(ShaderBindings& bindings, bool texelReads) const;

 private:
  struct Array {
    std::uint32_t binding;
    Buffer buffer;
  };
  const Context& context_;
  std::vector<Array> arrays_;        // the arrays read through texel views with the texel reads
  std::optional<Buffer> emitters_;   // the path shader's only; a storage buffer either way
};

// Whether the shader reads the scene through texel buffers: as `reads` says, Auto where
// `fit` (SceneUpload::texelsFit). Throws DeviceError for Texel on a scene that does not fit
// the device's `maxTexels`.
bool chooseTexelReads(SceneReads reads, bool fit, std::size_t maxTexels);

}  // namespace vkrt
