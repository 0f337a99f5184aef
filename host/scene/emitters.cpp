#include "scene/emitters.h"

#include <cmath>

#include "gpu_types.h"

namespace vkrt {

double emitterRadianceWeight(const Material& m) {
  if (m.quadLight >= 0) return 0.0;
  return std::abs(m.emission.x) + std::abs(m.emission.y) + std::abs(m.emission.z);
}

double sphereEmitterArea(const Sphere& s) {
  constexpr double kPi = 3.14159265358979323846;
  const double scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(s.worldFromObject))));
  return 4.0 * kPi * s.radius * s.radius * scale * scale;
}

EmitterTable collectEmitters(const SceneDesc& scene) {
  EmitterTable table;
  std::vector<double> weights;
  // The material's weight first: most primitives emit nothing, and their areas are not needed.
  auto radianceWeight = [&](std::uint32_t material) {
    return material < scene.materials.size() ? emitterRadianceWeight(scene.materials[material]) : 0.0;
  };
  auto add = [&](std::uint32_t prim, double weight) {
    if (weight > 0.0 && std::isfinite(weight)) table.prims.push_back(prim), weights.push_back(weight);
  };
  for (std::uint32_t i = 0; i < scene.triangles.size(); ++i) {
    const Triangle& t = scene.triangles[i];
    const double e = radianceWeight(t.material);
    if (e > 0.0) add(i, 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])) * e);
  }
  for (std::uint32_t i = 0; i < scene.spheres.size(); ++i) {
    const double e = radianceWeight(scene.spheres[i].material);
    if (e > 0.0) add(gpu::primRef(gpu::kPrimSphere, i), sphereEmitterArea(scene.spheres[i]) * e);
  }
  for (double w : weights) table.totalWeight += w;
  double running = 0.0;
  for (double w : weights) {
    running += w;
    table.pick.push_back(w / table.totalWeight);
    table.cdf.push_back(running / table.totalWeight);
  }
  if (!table.cdf.empty()) table.cdf.back() = 1.0;
  return table;
}

}  // namespace vkrt
