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
// (bench/README.md, "Texel reads inlined"); a count of 64 KiB blocks that is not a power of
// two is the same for every scene.
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

// The bytes of a texel of the array at `binding` (ShaderBindings::bindTo).
std::size_t texelBytesAt(std::uint32_t binding) { return binding == gpu::kBindingPrimRefs ? kPrimRefTexel : kTexel; }

// The arrays an upload makes, each with its binding: f(binding, items) for each, the one list
// of them (the emitters, always a storage buffer, are not among them).
template <class F>
void forEachTexelArray(const GpuScene& scene, SceneArrays arrays, F&& f) {
#define VKRT_SHAPE_ARRAY(Type, member, name, kind, GpuType, binding) f(binding, scene.member);
  VKRT_SHAPES(VKRT_SHAPE_ARRAY)
#undef VKRT_SHAPE_ARRAY
  f(gpu::kBindingTriangleNormals, scene.triangleNormals);
  f(gpu::kBindingLights, scene.lights);
  f(gpu::kBindingMaterials, scene.materials);
  f(gpu::kBindingBvhNodes, scene.bvh.nodes);
  f(gpu::kBindingPrimRefs, scene.bvh.primRefs);
  if (arrays == SceneArrays::Path) f(gpu::kBindingQuadLights, scene.quadLights);
}

// The context, its pool left with the buffers of the sizes this upload takes.
const Context& withPoolFor(const Context& context, const GpuScene& scene, SceneArrays arrays) {
  std::vector<std::size_t> sizes;
  forEachTexelArray(scene, arrays, [&](std::uint32_t, const auto& items) {
    sizes.push_back(texelPaddedBytes(items.size() * sizeof(items[0])));
  });
  context.scenePool().retainSizes(sizes);
  return context;
}

}  // namespace

ShaderBindings::ShaderBindings(SceneArrays arrays, bool texelReads)
    : types(arrays == SceneArrays::Path ? gpu::kPathBindingCount : gpu::kBindingCount,
            VK_DESCRIPTOR_TYPE_STORAGE_BUFFER),
      buffers(types.size(), nullptr) {
  if (texelReads)
    forEachTexelArray(GpuScene{}, arrays, [&](std::uint32_t binding, const auto&) {
      types[binding] = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
    });
}

void ShaderBindings::bindTo(ComputePipeline& pipeline) const {
  for (std::uint32_t b = 0; b < types.size(); ++b) {
    if (types[b] == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
      pipeline.bind(b, *buffers[b]);
    else if (texelBytesAt(b) == kPrimRefTexel)
      pipeline.bindTexels(b, *buffers[b], VK_FORMAT_R32_UINT, kPrimRefTexel);
    else
      pipeline.bindTexels(b, *buffers[b], VK_FORMAT_R32G32B32A32_UINT, kTexel);
  }
}

SceneUpload::SceneUpload(const Context& context, const GpuScene& scene, SceneArrays arrays)
    : context_(withPoolFor(context, scene, arrays)) {
  forEachTexelArray(scene, arrays, [&](std::uint32_t binding, const auto& items) {
    arrays_.push_back({binding, texelArray(context, items)});
  });
  if (arrays == SceneArrays::Path) emitters_.emplace(Buffer::withContents(context, scene.emitters));
}

SceneUpload::~SceneUpload() {
  try {
    std::vector<Buffer> buffers;
    for (Array& a : arrays_) buffers.push_back(std::move(a.buffer));
    context_.scenePool().keep(std::move(buffers));
  } catch (...) {   // no memory for the list: the buffers are freed instead of kept
  }
}

bool texelsFitBeforeBvh(const GpuScene& scene, SceneArrays arrays, std::size_t maxTexels, bool wideBvh) {
  const std::size_t primitives = primitiveCount(scene);
  bool fit = true;
  // (The BVH's arrays are only sized here, by the primitives: another thread may be building
  // them. The wide BVH has the root and a block of 4 for each of at most primitives - 1
  // interior nodes: wide_bvh.h.)
  const std::size_t nodesPerPrimitive = wideBvh ? 4 : 2;
  forEachTexelArray(scene, arrays, [&](std::uint32_t binding, const auto& items) {
    const std::size_t count = binding == gpu::kBindingBvhNodes  ? std::max<std::size_t>(1, nodesPerPrimitive * primitives)
                              : binding == gpu::kBindingPrimRefs ? primitives
                                                                 : items.size();
    fit = fit && texelPaddedBytes(count * sizeof(items[0])) / texelBytesAt(binding) <= maxTexels;
  });
  return fit;
}

bool SceneUpload::texelsFit(std::size_t maxTexels) const {
  return std::all_of(arrays_.begin(), arrays_.end(),
                     [&](const Array& a) { return a.buffer.size() / texelBytesAt(a.binding) <= maxTexels; });
}

void SceneUpload::bind(ShaderBindings& bindings) const {
  for (const Array& a : arrays_) bindings.set(a.binding, a.buffer);
  if (emitters_) bindings.set(gpu::kBindingEmitters, *emitters_);
}

bool chooseTexelReads(SceneReads reads, SceneArrays arrays, bool fit, const VkPhysicalDeviceLimits& limits) {
  std::uint32_t views = 0;
  forEachTexelArray(GpuScene{}, arrays, [&](std::uint32_t, const auto&) { ++views; });
  const bool allowed = views <= limits.maxPerStageDescriptorStorageImages;
  const bool texel = reads == SceneReads::Texel || (reads == SceneReads::Auto && fit && allowed);
  if (texel && !fit)
    throw DeviceError("the scene is too large for texel-buffer reads on this device (limit " +
                      std::to_string(limits.maxTexelBufferElements) +
                      " texels); use storage-buffer reads (--reads storage)");
  return texel;
}

}  // namespace vkrt
