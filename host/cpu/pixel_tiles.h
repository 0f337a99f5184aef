// How both CPU renderers spread an image over threads: 16x16 tiles of a pixel region, taken
// in turn by every worker, each storing its pixels' radiance as float. Knows nothing of
// what a pixel's colour is.
#pragma once

#include <cstdint>
#include <functional>

#include "image/crop.h"
#include "image/radiance_image.h"
#include "util/ray_counts.h"
#include "scene/scene_desc.h"

namespace vkrt {

// The nearest float; beyond float's range, the largest float of that sign, and 0 for NaN (a
// plain cast would be undefined there): an image holds no NaN or infinity.
float toFloat(double c);

// Calls shade(x, y, counts) for every pixel (x, y) of `region` (full-image coordinates) on
// `threads` threads (0: every hardware thread) and stores its colour in `image` (the region's
// size) as float, counting non-finite colours. After each tile, progress(units done, units
// total), with `unitsPerPixel` units a pixel (1, or its samples); `stop` is polled between
// tiles. The workers' ray counts, summed, are stored in *counts (what it held is replaced).
void shadeTiles(const PixelRect& region, int threads, std::uint64_t unitsPerPixel,
                const std::function<dvec3(int x, int y, RayCounts& counts)>& shade, RadianceImage& image,
                const std::function<void(std::uint64_t, std::uint64_t)>& progress, const std::function<bool()>& stop,
                RayCounts* counts);

}  // namespace vkrt
