// Uploads the scene's arrays and binds them, for either Vulkan renderer.
#include "gpu/scene_upload.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer_pool.h"
#include "gpu/device_error.h"

namespace vkrt {

static_assert(sizeof(gpu::GpuQuadLight) == 16 * gpu::kQuadLightTexels, "the texel view of a quad light");

namespace {

// The bytes of a texel of the scene's arrays as the shaders read them (ShaderBindings::bindTo).
constexpr std::size_t kTexel = 16, kPrimRefTexel = 4;

// `bytes` rounded up to a count of 64 KiB blocks that is not a power of two and is at least 3.
// Lavapipe compiles a shader again for each new combination of two properties of its texel
// buffers' sizes (Mesa 22.3, lp_sampler_static_texture_state): whether the buffer's size is a
// power of two, and whether bits 8-15 of the view's size are zero (read through a union as
// the last mip level). Scenes whose arrays differed in either compiled the same shader twice
// (0.2-0.5 s each); a count of 64 KiB blocks that is not a power of two is the same for every
// scene.
std::size_t texelPaddedBytes(std::size_t bytes) {
  constexpr std::size_t kBlock = 65536;
  std::size_t blocks = std::max<std::size_t>((bytes + kBlock - 1) / kBlock, 3);
  while ((blocks & (blocks - 1)) == 0) ++blocks;
  return blocks * kBlock;
}

// An array the shaders may read through a texel view: padded to texelPaddedBytes, in a buffer
// of the context's pool (BufferPool) where one of that size is kept.
template <class T>
Buffer texelArray(const Context& context, const std::vector<T>& items) {
  const std::size_t bytes = items.size() * sizeof(T);
  Buffer b = context.scenePool().take(context, texelPaddedBytes(bytes));
  b.fill(items.data(), bytes);
  return b;
}

// The padded sizes of the arrays an upload makes: the texelArray calls of SceneUpload's
// constructor, one for one (an array left out here is freed from the pool, not reused).
std::vector<std::size_t> texelArraySizes(const GpuScene& scene, SceneArrays arrays) {
  std::vector<std::size_t> sizes;
  auto add = [&](const auto& items) { sizes.push_back(texelPaddedBytes(items.size() * sizeof(items[0]))); };
  add(scene.triangleNormals);
  add(scene.lights);
  add(scene.materials);
  add(scene.bvh.nodes);
  add(scene.bvh.primRefs);
#define VKRT_SHAPE_SIZE(Type, member, name, kind, GpuType, binding) add(scene.member);
  VKRT_SHAPES(VKRT_SHAPE_SIZE)
#undef VKRT_SHAPE_SIZE
  if (arrays == SceneArrays::Path) add(scene.quadLights);
  return sizes;
}

// The context, its pool left with the buffers of the sizes this upload takes.
const Context& withPoolFor(const Context& context, const GpuScene& scene, SceneArrays arrays) {
  context.scenePool().retainSizes(texelArraySizes(scene, arrays));
  return context;
}

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
    : context_(withPoolFor(context, scene, arrays)),
      normals_(texelArray(context, scene.triangleNormals)),
      lights_(texelArray(context, scene.lights)),
      materials_(texelArray(context, scene.materials)),
      nodes_(texelArray(context, scene.bvh.nodes)),
      primRefs_(texelArray(context, scene.bvh.primRefs)) {
#define VKRT_SHAPE_UPLOAD(Type, member, name, kind, GpuType, binding) \
  shapes_.push_back(texelArray(context, scene.member));
  VKRT_SHAPES(VKRT_SHAPE_UPLOAD)
#undef VKRT_SHAPE_UPLOAD
  if (arrays != SceneArrays::Path) return;
  quadLights_.emplace(texelArray(context, scene.quadLights));
  emitters_.emplace(Buffer::withContents(context, scene.emitters));
}

SceneUpload::~SceneUpload() {
  try {
    std::vector<Buffer> arrays;
    for (Buffer& b : shapes_) arrays.push_back(std::move(b));
    for (Buffer* b : {&normals_, &lights_, &materials_, &nodes_, &primRefs_}) arrays.push_back(std::move(*b));
    if (quadLights_) arrays.push_back(std::move(*quadLights_));
    context_.scenePool().keep(std::move(arrays));
  } catch (...) {   // no memory for the list: the buffers are freed instead of kept
  }
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
