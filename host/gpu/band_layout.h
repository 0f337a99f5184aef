// How the Vulkan renderers cut the pixels they compute into bands of rows, and a band into
// workgroups of 8x8 tiles; and the GpuRenderParams (gpu_types.h) that tell the shader so.
// Plain arithmetic, without the Vulkan API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "gpu_types.h"
#include "image/crop.h"
#include "scene/flatten.h"

namespace vkrt {

struct BandLayout {
  PixelRect region;                  // the pixels computed: the whole image or the crop
  std::uint32_t width = 0, height = 0;   // the region's size
  std::uint32_t bandHeight = 0;      // rows per band: a multiple of the tile, at most the region's height rounded up to one
  std::uint32_t tilesX = 0;          // tiles across the region
  std::uint32_t tilesInBand = 0;     // tiles in a band (of bandHeight rows)
  std::uint32_t groups = 0;          // workgroups of a band's dispatch: each takes a run of tilesPerGroup tiles
  std::uint32_t tilesPerGroup = 1;
  std::size_t bandPixels() const { return std::size_t{width} * bandHeight; }
  // The workgroups of a band of `rows` rows (a multiple of the tile's, at most bandHeight).
  std::uint32_t groupsFor(std::uint32_t rows) const {
    return (tilesX * (rows / gpu::kWorkgroupSize) + tilesPerGroup - 1) / tilesPerGroup;
  }
  std::uint64_t invocations() const { return std::uint64_t{groups} * gpu::kWorkgroupSize * gpu::kWorkgroupSize; }
};

// The region of `scene`'s image a render computes: `crop`, or the whole image.
PixelRect renderRegion(const GpuScene& scene, const std::optional<PixelRect>& crop);

// The bands of `region`: as many rows a band as keep its suspended state, `stateBytes` a pixel
// shared by `tilesPerGroup` pixels (an invocation's state serves one pixel of each of its
// group's tiles), within `maxStateBytes`; at least one tile's rows, at most the region's.
BandLayout bandLayout(const PixelRect& region, std::size_t stateBytes, std::size_t maxStateBytes,
                      std::uint32_t tilesPerGroup);

// The GpuRenderParams of a render of `scene` in `layout` with `maxDepth`, but for the step
// budget (BandBuffers sets it; left 0).
gpu::GpuRenderParams renderParams(const GpuScene& scene, const BandLayout& layout, std::uint32_t maxDepth);

// Whether every ray of a render tests each primitive of `scene` instead of walking its BVH
// (kSpecTestAll, both shaders): where `allowed` (the options' testAll), the BVH holds every
// primitive exactly once (`eachPrimitiveOnce`), each is of a kind the shaders' loop tests
// (triangles and spheres), and there are at most kTestAllMaxPrims of them, a sphere counting
// as two.
bool testsEveryPrimitive(const GpuScene& scene, bool allowed, bool eachPrimitiveOnce);
// Whether the built BVH of `scene` holds every primitive exactly once (none left out as one
// that can never be hit): testsEveryPrimitive's `eachPrimitiveOnce` at render time.
bool bvhHoldsEachPrimitiveOnce(const GpuScene& scene);

// Throws DeviceError for a scene beyond what the shaders take (more primitives than a
// traversal-stack entry can name), InternalError for a BVH deeper than their stack, or of
// another width than the shader's (`wideBvh`: VulkanOptions::wideBvh).
void checkShaderLimits(const GpuScene& scene, bool wideBvh);

}  // namespace vkrt
