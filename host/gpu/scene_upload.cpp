// Uploads the scene's arrays and binds them, for either Vulkan renderer.
#include "gpu/scene_upload.h"

#include <string>

#include "gpu/device_error.h"

namespace vkrt {

static_assert(sizeof(gpu::GpuQuadLight) == 16 * gpu::kQuadLightTexels, "the texel view of a quad light");

namespace {

// The bytes of a texel of the scene's arrays as the shaders read them (ShaderBindings::bindTo).
constexpr std::size_t kTexel = 16, kPrimRefTexel = 4;

}  // namespace

void ShaderBindings::bindTo(ComputePipeline& pipeline) const {
  for (std::uint32_t b = 0; b < types.size(); ++b) {
    if (types[b] == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
      pipeline.bindUniform(b, *buffers[b]);
    else if (types[b] == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
      pipeline.bind(b, *buffers[b]);
    else if (b == gpu::kBindingPrimRefs)
      pipeline.bindTexels(b, *buffers[b], VK_FORMAT_R32_UINT, kPrimRefTexel);
    else
      pipeline.bindTexels(b, *buffers[b], VK_FORMAT_R32G32B32A32_UINT, kTexel);
  }
}

SceneUpload::SceneUpload(const Context& context, const GpuScene& scene, SceneArrays arrays)
    : normals_(Buffer::withContents(context, scene.triangleNormals, true)),
      lights_(Buffer::withContents(context, scene.lights, true)),
      materials_(Buffer::withContents(context, scene.materials, true)),
      nodes_(Buffer::withContents(context, scene.bvh.nodes, true)),
      primRefs_(Buffer::withContents(context, scene.bvh.primRefs, true)) {
#define VKRT_SHAPE_UPLOAD(Type, member, name, kind, GpuType, binding) \
  shapes_.push_back(Buffer::withContents(context, scene.member, true));
  VKRT_SHAPES(VKRT_SHAPE_UPLOAD)
#undef VKRT_SHAPE_UPLOAD
  if (arrays != SceneArrays::Path) return;
  quadLights_.emplace(Buffer::withContents(context, scene.quadLights, true));
  emitters_.emplace(Buffer::withContents(context, scene.emitters));
}

bool SceneUpload::texelsFit(std::size_t maxTexels) const {
  bool fit = primRefs_.size() / 4 <= maxTexels;   // one uint a texel
  for (const Buffer* b : {&normals_, &lights_, &materials_, &nodes_}) fit = fit && b->size() / 16 <= maxTexels;
  for (const Buffer& b : shapes_) fit = fit && b.size() / 16 <= maxTexels;
  if (quadLights_) fit = fit && quadLights_->size() / 16 <= maxTexels;
  return fit;
}

void SceneUpload::bind(ShaderBindings& bindings, bool texelReads) const {
  const VkDescriptorType type = texelReads ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  // Each kind's array at its binding, in the order of the kinds.
  constexpr std::uint32_t kShapeBindings[] = {
#define VKRT_SHAPE_BINDING(Type, member, name, kind, GpuType, binding) binding,
      VKRT_SHAPES(VKRT_SHAPE_BINDING)
#undef VKRT_SHAPE_BINDING
  };
  for (std::size_t kind = 0; kind < shapes_.size(); ++kind) bindings.set(kShapeBindings[kind], shapes_[kind], type);
  bindings.set(gpu::kBindingTriangleNormals, normals_, type);
  bindings.set(gpu::kBindingLights, lights_, type);
  bindings.set(gpu::kBindingMaterials, materials_, type);
  bindings.set(gpu::kBindingBvhNodes, nodes_, type);
  bindings.set(gpu::kBindingPrimRefs, primRefs_, type);
  if (quadLights_) bindings.set(gpu::kBindingQuadLights, *quadLights_, type);
  if (emitters_) bindings.set(gpu::kBindingEmitters, *emitters_, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

bool chooseTexelReads(SceneReads reads, bool fit, std::size_t maxTexels) {
  const bool texel = reads == SceneReads::Texel || (reads == SceneReads::Auto && fit);
  if (texel && !fit)
    throw DeviceError("the scene is too large for texel-buffer reads on this device (limit " +
                      std::to_string(maxTexels) + " texels); use storage-buffer reads (--reads storage)");
  return texel;
}

}  // namespace vkrt
