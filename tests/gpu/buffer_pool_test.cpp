// The scene buffers a context keeps from one render for the next (host/gpu/buffer_pool.h):
// which buffer a take returns, and, end to end, that renders given another scene's buffers
// are the renders they would be on fresh ones.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "gpu/buffer_pool.h"
#include "gpu/vulkan_path_renderer.h"
#include "path_scenes.h"
#include "scene/flatten.h"
#include "test_support.h"

namespace vkrt {
namespace {

constexpr std::size_t kBlock = 65536;

// New buffers of these counts of 64 KiB blocks.
std::vector<Buffer> buffersOfBlocks(const Context& context, std::initializer_list<std::size_t> blocks) {
  std::vector<Buffer> buffers;
  for (std::size_t n : blocks) buffers.emplace_back(context, n * kBlock);
  return buffers;
}

TEST(BufferPool, TakesAKeptBufferOfTheSameSizeOnly) {
  VKRT_REQUIRE_GPU(context);
  BufferPool pool;
  std::vector<Buffer> buffers = buffersOfBlocks(*context, {3, 5});
  const VkBuffer three = buffers[0].handle(), five = buffers[1].handle();
  pool.keep(std::move(buffers));
  EXPECT_EQ(pool.kept(), 2u);
  Buffer other = pool.take(*context, kBlock * 6);   // no kept one of this size: a new one
  EXPECT_NE(other.handle(), three);
  EXPECT_NE(other.handle(), five);
  EXPECT_EQ(other.size(), kBlock * 6);
  Buffer again = pool.take(*context, kBlock * 5);
  EXPECT_EQ(again.handle(), five);
  EXPECT_EQ(pool.kept(), 1u);
  // Keeping replaces what was kept: the pool holds one scene's arrays at most.
  std::vector<Buffer> next;
  next.push_back(std::move(again));
  pool.keep(std::move(next));
  EXPECT_EQ(pool.kept(), 1u);
  EXPECT_EQ(pool.take(*context, kBlock * 5).handle(), five);
  EXPECT_EQ(pool.kept(), 0u);
}

// Arrays that add up to more than the pool's most are freed, not kept.
TEST(BufferPool, KeepsNothingAboveItsMost) {
  VKRT_REQUIRE_GPU(context);
  BufferPool pool(kBlock * 8);
  pool.keep(buffersOfBlocks(*context, {3, 5}));
  EXPECT_EQ(pool.kept(), 2u);
  pool.keep(buffersOfBlocks(*context, {5, 5}));
  EXPECT_EQ(pool.kept(), 0u);
}

// Before an upload, the pool frees what the upload will not take.
TEST(BufferPool, RetainsOnlyTheSizesAnUploadTakes) {
  VKRT_REQUIRE_GPU(context);
  BufferPool pool;
  std::vector<Buffer> buffers = buffersOfBlocks(*context, {3, 5, 5});
  const VkBuffer three = buffers[0].handle();
  pool.keep(std::move(buffers));
  pool.retainSizes({kBlock * 3, kBlock * 5, kBlock * 6});   // one of the two of 5 blocks
  EXPECT_EQ(pool.kept(), 2u);
  EXPECT_EQ(pool.take(*context, kBlock * 3).handle(), three);
  pool.retainSizes({kBlock * 6});
  EXPECT_EQ(pool.kept(), 0u);
}

// A fill zeroes what an earlier fill (an earlier scene) wrote beyond its own data.
TEST(BufferPool, FillZeroesWhatFollowsTheData) {
  VKRT_REQUIRE_GPU(context);
  Buffer b(*context, 4096);
  const std::vector<unsigned char> earlier(4096, 0xAB);
  b.fill(earlier.data(), earlier.size());
  const std::uint32_t data[] = {1, 2, 3};
  b.fill(data, sizeof data);
  const auto* bytes = static_cast<const unsigned char*>(b.mapped());
  EXPECT_EQ(std::memcmp(bytes, data, sizeof data), 0);
  for (std::size_t i = sizeof data; i < b.size(); ++i) ASSERT_EQ(bytes[i], 0u) << i;
}

// A new buffer's first fill zeroes what follows the data too: lavapipe's buffer memory comes
// from malloc, freed memory handed back as it was, and the path shader reads past a scene
// array's data (the record after the last triangle), where denormal floats slowed every ray
// (host/gpu/buffer.h). The bytes written here before the fill are what such memory held.
TEST(BufferPool, AFirstFillZeroesWhatANewBuffersMemoryHeld) {
  VKRT_REQUIRE_GPU(context);
  Buffer b(*context, 4096);
  const std::vector<std::uint32_t> held(b.size() / 4, 0x00007fffu);   // a pointer's upper half: a denormal float
  std::memcpy(b.mapped(), held.data(), b.size());
  const std::uint32_t data[] = {1, 2, 3};
  b.fill(data, sizeof data);
  const auto* bytes = static_cast<const unsigned char*>(b.mapped());
  EXPECT_EQ(std::memcmp(bytes, data, sizeof data), 0);
  for (std::size_t i = sizeof data; i < b.size(); ++i) ASSERT_EQ(bytes[i], 0u) << i;
}

// A render on the buffers of another scene (the same padded sizes, other contents) is the
// render of its own scene, bit for bit: B, then A, then B again on one context.
TEST(BufferPool, ARenderOnAnotherScenesBuffersChangesNoBit) {
  VKRT_REQUIRE_GPU(context);
  const int before = context->validationMessages();
  const GpuScene a = flatten(test::emissiveSurfacesBox(10, 3)), b = flatten(test::cornellLikeBox(10, 3));
  VulkanPathOptions o;
  o.seed = 3;
  o.sampleCount = 2;
  RadianceImage first = renderVulkanPath(*context, b, o, nullptr, nullptr);
  EXPECT_GT(context->scenePool().kept(), 0u);   // the render's arrays, kept for the next
  RadianceImage other = renderVulkanPath(*context, a, o, nullptr, nullptr);
  RadianceImage again = renderVulkanPath(*context, b, o, nullptr, nullptr);
  EXPECT_FALSE(test::sameBits(first, other));
  EXPECT_TRUE(test::sameBits(first, again));
  EXPECT_EQ(context->validationMessages(), before) << "the Vulkan validation layer reported problems (see stderr)";
}

}  // namespace
}  // namespace vkrt
