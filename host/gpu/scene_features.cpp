#include "gpu/scene_features.h"

#include "gpu_render.h"

namespace vkrt {

void setSharedFeatures(const GpuScene& scene, std::vector<std::uint32_t>& spec) {
  bool point = false, directional = false, attenuation = false;
  for (const gpu::GpuLight& l : scene.lights) {
    const bool isPoint = l.kind == gpu::kLightPoint;
    (isPoint ? point : directional) = true;
    if (isPoint && (l.attenuation0 != 1.0f || l.attenuation1 != 0.0f || l.attenuation2 != 0.0f)) attenuation = true;
  }
  spec[gpu::kSpecHasTriangles] = !scene.triangles.empty();
  spec[gpu::kSpecHasSpheres] = !scene.spheres.empty();
  spec[gpu::kSpecHasSmoothNormals] = !scene.triangleNormals.empty();
  spec[gpu::kSpecHasPointLights] = point;
  spec[gpu::kSpecHasDirectionalLights] = directional;
  spec[gpu::kSpecHasAttenuation] = attenuation;
}

std::string leftOutNames(const std::vector<std::uint32_t>& spec, std::initializer_list<FeatureName> own) {
  static constexpr FeatureName kShared[] = {{gpu::kSpecHasTriangles, "triangles"},
                                            {gpu::kSpecHasSpheres, "spheres"},
                                            {gpu::kSpecHasSmoothNormals, "smooth normals"},
                                            {gpu::kSpecHasPointLights, "point lights"},
                                            {gpu::kSpecHasDirectionalLights, "directional lights"},
                                            {gpu::kSpecHasAttenuation, "attenuation"}};
  std::string names;
  auto add = [&](const FeatureName& f) {
    if (!spec[f.id]) names += (names.empty() ? "" : ", ") + std::string(f.name);
  };
  for (const FeatureName& f : kShared) add(f);
  for (const FeatureName& f : own) add(f);
  return names;
}

}  // namespace vkrt
