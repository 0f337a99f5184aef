// CPU reference of the path integrators (doc/path-tracing.md, "Quad lights"; doc/path-tracing.md, "Estimators"): analyticdirect,
// direct and pathtracer, in double precision, written plainly and apart from the shader. It
// draws the shader's random numbers (gpu_types.h, rngUniform) by the same rules, so that one
// seed gives the same paths on both backends up to rounding. Knows nothing of Vulkan.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>

#include "image/crop.h"
#include "image/radiance_image.h"
#include "util/ray_counts.h"
#include "scene/bvh.h"
#include "scene/scene_desc.h"

namespace vkrt {

struct PathOptions {
  int threads = 0;                // 0: every hardware thread
  std::uint32_t seed = 0;         // the random generator's seed (gpu_types.h)
  // Samples [firstSample, firstSample + sampleCount) of the render whose total is
  // scene.path.spp (a render of spp 1 samples the pixel centres); sampleCount 0: every sample
  // from firstSample on. Batches of one render draw different numbers, so that their images,
  // averaged with their sample counts as weights, are the full render's (up to float rounding).
  std::uint32_t firstSample = 0;
  std::uint32_t sampleCount = 0;
  // Stratified samples over scene.path.spp (gpu_rng.h, rngStratify); false: independent ones.
  bool stratified = false;
  // Only these pixels of the scene's image (inside it), as an image of the crop's size; camera
  // rays and random numbers are the full image's, so a crop's pixels are a full render's.
  std::optional<PixelRect> crop;
  // Called after each finished tile with (pixel samples done, pixel samples total), from
  // worker threads (one at a time).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
  // Polled between tiles, from worker threads: true stops early (the image is then incomplete).
  std::function<bool()> stop;
};

// Renders scene.path.integrator (AnalyticDirect, Direct or PathTracer; throws
// std::invalid_argument for Raytracer): each pixel the mean radiance of its samples, linear,
// with RadianceImage::samples = the samples taken. `counts` (optional) gets the rays traced;
// counts->reflection counts the paths' scattered rays, and counts->nonFinite the pixels whose
// mean is NaN or infinite.
RadianceImage renderPathReference(const SceneDesc& scene, const Bvh& bvh, const PathOptions& options,
                                  RayCounts* counts);

// analyticdirect's irradiance factor of one quad light at point x of normal n: Phi(x) . n of
// doc/path-tracing.md, "Integrators" (the radiance to add is kd / pi * L * this), 0 when x is not in
// front of the light (it emits on one side only).
double analyticQuadFactor(const QuadLight& light, const dvec3& x, const dvec3& n);

}  // namespace vkrt
