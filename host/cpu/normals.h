// The normals view's CPU reference (vkrt --view normals): each pixel's colour is the unit
// surface normal where the camera ray through its centre first hits, n * 0.5 + 0.5 (x, y, z as
// red, green and blue), black where it hits nothing. Double precision, apart from the shader
// (shaders/normals.comp).
#pragma once

#include "cpu/reference.h"

namespace vkrt {

// As renderReference: the options' region, threads, samples (identical: one is traced),
// progress, stop and rows. Counts a camera ray a pixel.
RadianceImage renderNormals(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options, RayCounts* counts);

}  // namespace vkrt
