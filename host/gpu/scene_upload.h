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

// Which arrays a shader reads: the Whitted shader's (triangles .. primitive references), or
// the path shader's (also quad lights and emitters).
enum class SceneArrays { Whitted, Path };

// A shader's bindings 0..N-1: a descriptor type and a buffer each.
struct ShaderBindings {
  // The bindings of the Whitted shader (SceneArrays::Whitted) or the path shader, their types
  // set, no buffer yet: the scene's arrays storage texel buffers (texelReads) or storage
  // buffers, the rest (the render's and the path's parameters, pixels, states, counters,
  // emitters) storage buffers. The one table of the types, which a pipeline made
  // ahead (ComputePipeline::prepare) and the render's own take alike.
  ShaderBindings(SceneArrays arrays, bool texelReads);
  void set(std::uint32_t binding, const Buffer& buffer) { buffers[binding] = &buffer; }
  // Binds each buffer at its binding, as its type says: a storage texel buffer as a view of
  // uints (the primitive references) or of uvec4 texels (the rest).
  void bindTo(ComputePipeline& pipeline) const;
  std::vector<VkDescriptorType> types;
  std::vector<const Buffer*> buffers;
};

class SceneUpload {
 public:
  SceneUpload(const Context& context, const GpuScene& scene, SceneArrays arrays);
  ~SceneUpload();   // gives the arrays' buffers to the context's pool, for the next upload
  SceneUpload(const SceneUpload&) = delete;
  SceneUpload& operator=(const SceneUpload&) = delete;
  // Whether every array read through a texel view fits `maxTexels` texels.
  bool texelsFit(std::size_t maxTexels) const;
  // Sets the scene's buffers at their bindings.
  void bind(ShaderBindings& bindings) const;

 private:
  struct Array {
    std::uint32_t binding;
    Buffer buffer;
  };
  const Context& context_;
  std::vector<Array> arrays_;        // the arrays read through texel views with the texel reads
  std::optional<Buffer> emitters_;   // the path shader's only; a storage buffer either way
};

// SceneUpload::texelsFit of `scene` before its BVH is built (scene.bvh empty), with the BVH
// at its largest: 2n nodes (4n when `wideBvh`: scene/wide_bvh.h) and n references for n
// primitives (a guess for a pipeline made ahead, which the render's own check confirms).
bool texelsFitBeforeBvh(const GpuScene& scene, SceneArrays arrays, std::size_t maxTexels, bool wideBvh);

// Whether the shader reads the scene through texel buffers: as `reads` says, Auto where
// `fit` (SceneUpload::texelsFit with the device's maxTexelBufferElements) and the device
// allows a shader as many storage texel buffers as `arrays` has (Vulkan guarantees only 4).
// Throws DeviceError for Texel on a scene that does not fit; Texel on a device that allows
// too few is the pipeline's DeviceError (checkBindingLimits).
bool chooseTexelReads(SceneReads reads, SceneArrays arrays, bool fit, const VkPhysicalDeviceLimits& limits);

}  // namespace vkrt
