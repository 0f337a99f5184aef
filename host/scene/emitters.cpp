#include "scene/emitters.h"

#include <cmath>

#include "gpu_types.h"
#include "scene/shapes/shape.h"

namespace vkrt {

double emitterRadianceWeight(const Material& m) {
  if (m.quadLight >= 0) return 0.0;
  return std::abs(m.emission.x) + std::abs(m.emission.y) + std::abs(m.emission.z);
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
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind)
    for (std::uint32_t i = 0; i < shapes::count(scene, kind); ++i) {
      const std::uint32_t ref = gpu::primRef(kind, i);
      const double e = radianceWeight(shapes::material(scene, ref));
      if (e > 0.0) add(ref, shapes::area(scene, ref) * e);
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
