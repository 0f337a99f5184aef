// CPU reference renderer: SceneDesc (+ its BVH) -> RadianceImage, in double precision, written
// plainly after doc/scene-format.md, "Camera"; doc/scene-format.md, "Conventions". It is the tests' oracle for the GPU backend, so it shares
// no intersection or shading code with the shader.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "image/crop.h"
#include "image/radiance_image.h"
#include "image/row_sink.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/scene_desc.h"

namespace vkrt {

struct CpuOptions {
  int threads = 0;   // 0: every hardware thread
  // Called after each finished tile with (pixels done, pixels total), from worker threads
  // (one at a time).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
  // Polled between tiles, from worker threads: true stops early (the image is then incomplete).
  std::function<bool()> stop;
  // Only these pixels of the scene's image (inside it), as an image of the crop's size; the
  // camera rays are the full image's (doc/scene-format.md, "Camera").
  std::optional<PixelRect> crop;
  // The samples to render: [firstSample, firstSample + sampleCount) of each pixel, drawn with
  // `seed` (gpu_types.h, "Random numbers"); the image returned is their mean, with
  // RadianceImage::samples = sampleCount. The Whitted model (Integrator::Raytracer) is
  // deterministic: every sample is the same, so it traces one and ignores the seed.
  std::uint32_t seed = 0;
  std::uint64_t firstSample = 0;
  std::uint32_t sampleCount = 1;
  // When set, the image is rendered in bands of rows, each handed to `rows` when finished
  // (image/row_sink.h) and not kept: memory grows with the width, not the image, and the
  // image returned has no pixels. Rows are relative to the region (the crop's top is 0).
  RowSink rows;
  std::size_t bandPixels = 1u << 20;   // with `rows`: about this many pixels a band (12 MB of floats)
};

// The Whitted model of doc/scene-format.md, "Camera"; doc/scene-format.md, "Conventions" (the path integrators plug in beside it, for
// scene.path.integrator != Integrator::Raytracer).
RadianceImage renderReference(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options, RayCounts* counts);

// What every technique of one deterministic sample a pixel shares (the Whitted model, the views):
// shade(x, y, counts) for each pixel of the options' region (crop) on its threads, into an image
// whose samples are options.sampleCount, or with options.rows in bands handed there.
RadianceImage shadeEachPixelOnce(const SceneDesc& scene, const CpuOptions& options,
                                 const std::function<dvec3(int x, int y, RayCounts& counts)>& shade,
                                 RayCounts* counts);

}  // namespace vkrt
