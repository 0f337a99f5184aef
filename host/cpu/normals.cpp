// The normals view on the CPU: a camera ray a pixel, its nearest hit, the normal there.
#include "cpu/normals.h"

#include "cpu/scene_query.h"

namespace vkrt {

RadianceImage renderNormals(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options, RayCounts* counts) {
  const SceneQuery query(scene, bvh);
  return shadeEachPixelOnce(
      scene, options,
      [&](int x, int y, RayCounts& local) {
        ++local.primary;
        const Ray ray = query.cameraRay(x + 0.5, y + 0.5);
        Hit hit;
        if (!query.intersect(ray, 0.0, kInfinity, false, hit)) return dvec3(0.0);   // a miss is black
        dvec3 normal;
        query.surfaceAt(hit, ray.origin + hit.t * ray.dir, normal);
        return normal * 0.5 + 0.5;
      },
      counts);
}

}  // namespace vkrt
