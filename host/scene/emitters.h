// The emissive triangles and spheres that next-event estimation samples as lights (beyond the
// course; quad lights are sampled as quad lights): which primitives, and the probability with
// which a light sample picks each, proportional to area x sum(|emission|). One rule for both
// backends: the CPU reference keeps the double weights, flatten() rounds the cumulative
// probabilities to float for the shader. Depends on the scene description only.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene_desc.h"

namespace vkrt {

// sum(|emission|) of a material that is no quad light's, else 0: the weight per unit area
// (of shapes::area, scene/shapes/shape.h).
double emitterRadianceWeight(const Material& m);

struct EmitterTable {
  std::vector<std::uint32_t> prims;   // primRefs (gpu_types.h: primRef(kind, index)), triangles first
  std::vector<double> pick;           // the probability of picking each
  std::vector<double> cdf;            // cumulative: cdf[e] = pick[0] + ... + pick[e], the last exactly 1
  double totalWeight = 0.0;           // sum of area x sum(|emission|): pick = weight / totalWeight
};

// Every triangle and sphere of positive weight, in scene order.
EmitterTable collectEmitters(const SceneDesc& scene);

}  // namespace vkrt
