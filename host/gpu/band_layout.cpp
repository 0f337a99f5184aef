// Band sizing and the render parameters both Vulkan renderers share.
#include "gpu/band_layout.h"

#include <algorithm>
#include <string>

#include "util/errors.h"
#include "gpu/device_error.h"
#include "gpu/tile_order.h"

namespace vkrt {

PixelRect renderRegion(const GpuScene& scene, const std::optional<PixelRect>& crop) {
  return crop ? *crop : PixelRect{0, 0, static_cast<int>(scene.width), static_cast<int>(scene.height)};
}

BandLayout bandLayout(const PixelRect& region, std::size_t stateBytes, std::size_t maxStateBytes,
                      std::uint32_t tilesPerGroup) {
  const std::uint32_t tile = gpu::kWorkgroupSize;
  BandLayout b;
  b.region = region;
  b.width = static_cast<std::uint32_t>(region.width());
  b.height = static_cast<std::uint32_t>(region.height());
  const std::size_t rowsByMemory = maxStateBytes * tilesPerGroup / (stateBytes * b.width);
  b.bandHeight = static_cast<std::uint32_t>(std::max<std::size_t>(tile, rowsByMemory / tile * tile));
  b.bandHeight = std::min(b.bandHeight, (b.height + tile - 1) / tile * tile);
  b.tilesX = (b.width + tile - 1) / tile;
  b.tilesInBand = b.tilesX * (b.bandHeight / tile);
  b.tilesPerGroup = tilesPerGroup;
  b.groups = b.groupsFor(b.bandHeight);
  return b;
}

gpu::GpuRenderParams renderParams(const GpuScene& scene, const BandLayout& layout, std::uint32_t maxDepth) {
  gpu::GpuRenderParams params{};
  params.width = layout.width;
  params.height = layout.height;
  params.maxDepth = maxDepth;
  params.lightCount = static_cast<std::uint32_t>(scene.lights.size());
  params.bandHeight = layout.bandHeight;
  params.tilesX = layout.tilesX;
  params.tileOrderStride = scatterStride(layout.groups);   // the order of the workgroups' runs of tiles
  params.primCount = static_cast<std::uint32_t>(scene.bvh.primRefs.size());
  const gpu::GpuBvhNode& root = scene.bvh.nodes[0];
  params.rootEntry = root.primCount > 0 ? gpu::kStackLeafBit | root.primCount << gpu::kStackCountShift |
                                              root.leftOrFirst
                                        : root.leftOrFirst;
  params.originX = static_cast<std::uint32_t>(layout.region.x0);
  params.originY = static_cast<std::uint32_t>(layout.region.y0);
  params.fullWidth = scene.width;
  params.fullHeight = scene.height;
  params.triangleCount = static_cast<std::uint32_t>(scene.triangles.size());
  params.sphereCount = static_cast<std::uint32_t>(scene.spheres.size());
  return params;
}

bool testsEveryPrimitive(const GpuScene& scene, bool allowed, bool eachPrimitiveOnce) {
  const std::size_t primitives = primitiveCount(scene);
  return allowed && eachPrimitiveOnce && primitives == scene.triangles.size() + scene.spheres.size() &&
         scene.triangles.size() + 2 * scene.spheres.size() <= gpu::kTestAllMaxPrims;
}

bool bvhHoldsEachPrimitiveOnce(const GpuScene& scene) {
  return scene.bvh.primRefs.size() == primitiveCount(scene);
}

void checkShaderLimits(const GpuScene& scene, bool wideBvh) {
  // The shader walks the BVH as the upload holds it.
  if (scene.bvh.wide != wideBvh)
    throw InternalError(std::string("the shader walks a ") + (wideBvh ? "wide" : "binary") + " BVH, the scene's is " +
                        (scene.bvh.wide ? "wide" : "binary"));
  // The shaders pack a leaf's first primRef into 28 bits (kStackFirstMask).
  if (scene.bvh.primRefs.size() > gpu::kStackFirstMask)
    throw DeviceError("the scene has " + std::to_string(scene.bvh.primRefs.size()) +
                      " primitives; the Vulkan backend takes at most " + std::to_string(gpu::kStackFirstMask) +
                      " (--backend cpu has no such limit)");
  // The traversal stack has a fixed size; the builder keeps the BVH within it.
  if (scene.bvh.depth + 1 > static_cast<int>(gpu::kTraversalStackSize))
    throw InternalError("BVH depth " + std::to_string(scene.bvh.depth) + " exceeds the traversal stack");
}

}  // namespace vkrt
