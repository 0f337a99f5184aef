// The shader sees exactly the bytes the host wrote: every struct of gpu_types.h goes through
// layout_probe.comp, which copies it out field by field. And the shaders' bindings against a
// device's limits.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/compute_pipeline.h"
#include "gpu/device_error.h"
#include "gpu/scene_upload.h"
#include "layout_probe.comp.h"
#include "test_support.h"

using namespace vkrt;

namespace {

// Two elements whose bytes are all distinct, so a wrong offset or stride shows.
template <class T>
std::vector<T> patterned(std::uint32_t seed) {
  std::vector<T> v(2);
  auto* words = reinterpret_cast<std::uint32_t*>(v.data());
  for (std::size_t i = 0; i < sizeof(T) * 2 / 4; ++i) {
    // Finite float bit patterns: exponent bits kept away from all-ones.
    words[i] = 0x3F000000u + seed * 0x10000u + static_cast<std::uint32_t>(i);
  }
  return v;
}

template <class T>
void appendSecond(std::vector<std::uint32_t>& expected, const std::vector<T>& v) {
  const auto* words = reinterpret_cast<const std::uint32_t*>(&v[1]);
  expected.insert(expected.end(), words, words + sizeof(T) / 4);
}

}  // namespace

TEST(GpuLayout, ShaderReadsExactlyTheBytesTheHostWrote) {
  VKRT_REQUIRE_GPU(context);
  auto triangles = patterned<gpu::GpuTriangle>(1);
  auto normals = patterned<gpu::GpuTriangleNormals>(2);
  auto spheres = patterned<gpu::GpuSphere>(3);
  auto lights = patterned<gpu::GpuLight>(4);
  auto materials = patterned<gpu::GpuMaterial>(5);
  auto nodes = patterned<gpu::GpuBvhNode>(6);
  auto params = patterned<gpu::GpuRenderParams>(7);
  auto quadLights = patterned<gpu::GpuQuadLight>(8);
  auto pathParams = patterned<gpu::GpuPathParams>(9);
  auto emitters = patterned<gpu::GpuEmitter>(10);
  auto whittedStates = patterned<gpu::GpuWhittedState>(11);
  auto pathStates = patterned<gpu::GpuPathTracerState>(12);
  auto counters = patterned<gpu::GpuCounters>(13);
  auto pathPush = patterned<gpu::GpuPathPush>(14);
  auto push = patterned<gpu::GpuPushConstants>(15);
  std::vector<std::uint32_t> expected;
  appendSecond(expected, triangles);
  appendSecond(expected, normals);
  appendSecond(expected, spheres);
  appendSecond(expected, lights);
  appendSecond(expected, materials);
  appendSecond(expected, nodes);
  const auto* paramWords = reinterpret_cast<const std::uint32_t*>(&params[0]);   // one element, not an array
  expected.insert(expected.end(), paramWords, paramWords + sizeof(gpu::GpuRenderParams) / 4);
  appendSecond(expected, quadLights);
  const auto* pathWords = reinterpret_cast<const std::uint32_t*>(&pathParams[0]);
  expected.insert(expected.end(), pathWords, pathWords + sizeof(gpu::GpuPathParams) / 4);
  appendSecond(expected, emitters);
  appendSecond(expected, whittedStates);
  appendSecond(expected, pathStates);
  appendSecond(expected, counters);
  appendSecond(expected, pathPush);
  const auto* pushWords = reinterpret_cast<const std::uint32_t*>(&push[0]);
  expected.insert(expected.end(), pushWords, pushWords + sizeof(gpu::GpuPushConstants) / 4);

  Buffer b0 = Buffer::withContents(*context, triangles), b1 = Buffer::withContents(*context, normals),
         b2 = Buffer::withContents(*context, spheres), b3 = Buffer::withContents(*context, lights),
         b4 = Buffer::withContents(*context, materials), b5 = Buffer::withContents(*context, nodes),
         b6 = Buffer::withContents(*context, params), b8 = Buffer::withContents(*context, quadLights),
         b9 = Buffer::withContents(*context, pathParams), b10 = Buffer::withContents(*context, emitters),
         b11 = Buffer::withContents(*context, whittedStates), b12 = Buffer::withContents(*context, pathStates),
         b13 = Buffer::withContents(*context, counters), b14 = Buffer::withContents(*context, pathPush);
  Buffer out(*context, expected.size() * 4, true);
  std::vector<VkDescriptorType> types(15, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  ComputePipeline probe(*context, kLayoutProbeSpirv, sizeof(kLayoutProbeSpirv), types, {},
                        sizeof(gpu::GpuPushConstants));
  const Buffer* all[] = {&b0, &b1, &b2, &b3, &b4, &b5, &b6, &out, &b8, &b9, &b10, &b11, &b12, &b13, &b14};
  for (std::uint32_t i = 0; i < 15; ++i) probe.bind(i, *all[i]);
  probe.run(push.data(), 1);
  std::vector<std::uint32_t> got(expected.size());
  std::memcpy(got.data(), out.mapped(), got.size() * 4);
  for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(got[i], expected[i]) << "word " << i;
  EXPECT_EQ(context->validationMessages(), 0);
}

// A device that allows a compute shader fewer bindings of a kind than a shader has is a
// device error naming the device and both numbers, before any pipeline is made; Vulkan's
// minimums (4 storage buffers, 4 storage images) fit neither the texel-read Whitted shader
// (7 storage texel buffers) nor the storage-read path shader (its scene arrays are storage
// buffers), and generous limits fit both.
TEST(GpuLayout, BindingsBeyondTheDeviceLimitsAreADeviceError) {
  VkPhysicalDeviceLimits minimum{};
  minimum.maxPerStageDescriptorStorageBuffers = 4;
  minimum.maxPerStageDescriptorStorageImages = 4;
  minimum.maxPerStageResources = 128;
  const std::vector<VkDescriptorType> whittedTexel = ShaderBindings(SceneArrays::Whitted, true).types;
  const std::vector<VkDescriptorType> pathStorage = ShaderBindings(SceneArrays::Path, false).types;
  try {
    checkBindingLimits(minimum, "small", whittedTexel);
    ADD_FAILURE() << "the texel-read Whitted shader fit in 4 storage images";
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'small' allows a compute shader 4 storage texel buffers"), std::string::npos)
        << message;
    EXPECT_NE(message.find("--reads storage"), std::string::npos) << message;
  }
  try {
    checkBindingLimits(minimum, "small", pathStorage);
    ADD_FAILURE() << "the storage-read path shader fit in 4 storage buffers";
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'small' allows a compute shader 4 storage buffers"), std::string::npos) << message;
    const auto storage = std::count(pathStorage.begin(), pathStorage.end(), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    EXPECT_NE(message.find("needs " + std::to_string(storage)), std::string::npos) << message;
  }
  VkPhysicalDeviceLimits generous = minimum;
  generous.maxPerStageDescriptorStorageBuffers = 64;
  generous.maxPerStageDescriptorStorageImages = 64;
  EXPECT_NO_THROW(checkBindingLimits(generous, "g", whittedTexel));
  VkPhysicalDeviceLimits fewResources = generous;
  fewResources.maxPerStageResources = 3;
  EXPECT_THROW(checkBindingLimits(fewResources, "r", whittedTexel), DeviceError);
  fewResources.maxPerStageResources = 64;
  EXPECT_NO_THROW(checkBindingLimits(fewResources, "r", pathStorage));
}

// `--reads auto` takes texel reads only where the scene fits the texel-count limit and the
// device allows the shader a storage texel buffer per scene array: the Whitted shader has 7,
// the path shader 8, and Vulkan guarantees 4. `--reads texel` on a scene that does not fit is
// a device error naming the limit.
TEST(GpuLayout, AutoReadsTakeTexelsOnlyWhereTheDeviceAllowsThem) {
  VkPhysicalDeviceLimits limits{};
  limits.maxTexelBufferElements = 1000;
  limits.maxPerStageDescriptorStorageImages = 8;
  EXPECT_TRUE(chooseTexelReads(SceneReads::Auto, SceneArrays::Whitted, true, limits));
  EXPECT_TRUE(chooseTexelReads(SceneReads::Auto, SceneArrays::Path, true, limits));
  EXPECT_FALSE(chooseTexelReads(SceneReads::Auto, SceneArrays::Path, false, limits));
  EXPECT_FALSE(chooseTexelReads(SceneReads::Storage, SceneArrays::Path, true, limits));
  limits.maxPerStageDescriptorStorageImages = 7;
  EXPECT_TRUE(chooseTexelReads(SceneReads::Auto, SceneArrays::Whitted, true, limits));
  EXPECT_FALSE(chooseTexelReads(SceneReads::Auto, SceneArrays::Path, true, limits));
  limits.maxPerStageDescriptorStorageImages = 4;
  EXPECT_FALSE(chooseTexelReads(SceneReads::Auto, SceneArrays::Whitted, true, limits));
  EXPECT_TRUE(chooseTexelReads(SceneReads::Texel, SceneArrays::Whitted, true, limits));
  try {
    chooseTexelReads(SceneReads::Texel, SceneArrays::Whitted, false, limits);
    ADD_FAILURE() << "--reads texel took a scene beyond the texel limit";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("limit 1000 texels"), std::string::npos) << e.what();
  }
}
