// The secondary-ray offset's scene scale (the policy: gpu_types.h, "Secondary rays").
#include "scene/ray_offset.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gpu_types.h"
#include "scene/bvh.h"

namespace vkrt {

bool sceneBounds(const SceneDesc& scene, dvec3& boxLo, dvec3& boxHi) {
  dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : scene.triangles)
    for (const dvec3& p : t.p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  for (const Sphere& s : scene.spheres) {
    dvec3 slo, shi;
    sphereBounds(s, slo, shi);
    lo = glm::min(lo, slo);
    hi = glm::max(hi, shi);
  }
  if (!(lo.x <= hi.x)) return false;
  boxLo = lo;
  boxHi = hi;
  return true;
}

double sceneSize(const SceneDesc& scene) {
  dvec3 lo, hi;
  return sceneBounds(scene, lo, hi) ? glm::length(hi - lo) : 0.0;
}

double secondaryRayEpsilon(const SceneDesc& scene) {
  const double base = gpu::kSecondaryRayTMin;
  double size = sceneSize(scene);
  if (!(size > 0.0) || !std::isfinite(size)) return base;
  // Whole decades away from the course's sizes: 0 for the course's scenes (their images stay
  // as they were), and exactly k under scaling by 10^k.
  double decades = 0.0;
  if (size < gpu::kCourseSceneSizeLow) decades = -std::ceil(std::log10(gpu::kCourseSceneSizeLow / size));
  if (size > gpu::kCourseSceneSizeHigh) decades = std::ceil(std::log10(size / gpu::kCourseSceneSizeHigh));
  return base * std::pow(10.0, decades);
}

double secondaryRayTMin(double sceneEpsilon, const dvec3& p) {
  double magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return std::max(sceneEpsilon, double{gpu::kOffsetPerMagnitude} * magnitude);
}

}  // namespace vkrt
