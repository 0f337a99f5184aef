// SceneDesc -> GpuScene. The only place where double-precision scene data becomes float32.
#include "scene/flatten.h"

#include <cmath>

namespace vkrt {
namespace {

gpu::vec4 f4(const dvec3& v, float w = 0.0f) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), w};
}

// The camera basis in double, then float: a per-pixel step right and up, and the back vector.
gpu::GpuPushConstants cameraConstants(const SceneDesc& scene) {
  const Camera& c = scene.camera;
  dvec3 w = glm::normalize(c.from - c.at);
  dvec3 u = glm::normalize(glm::cross(c.up, w));
  dvec3 v = glm::cross(w, u);
  double tanY = std::tan(glm::radians(c.fovyDegrees) / 2.0);
  double tanX = tanY * scene.width / scene.height;
  gpu::GpuPushConstants p{};
  p.cameraOrigin = f4(c.from);
  p.cameraRight = f4(u * (tanX / (scene.width / 2.0)));
  p.cameraUp = f4(v * (tanY / (scene.height / 2.0)));
  p.cameraBack = f4(w);
  return p;
}

}  // namespace

GpuScene flatten(const SceneDesc& scene) {
  GpuScene g;
  g.width = static_cast<std::uint32_t>(scene.width);
  g.height = static_cast<std::uint32_t>(scene.height);
  g.maxDepth = static_cast<std::uint32_t>(scene.maxDepth);
  g.camera = cameraConstants(scene);
  g.triangles.reserve(scene.triangles.size());
  for (const Triangle& t : scene.triangles) {
    gpu::GpuTriangle gt{};
    gt.p0 = f4(t.p[0]);
    gt.p1 = f4(t.p[1]);
    gt.p2 = f4(t.p[2]);
    gt.materialIndex = t.material;
    gt.normalsIndex = gpu::kNoNormals;
    if (t.smooth) {
      gt.normalsIndex = static_cast<gpu::uint>(g.triangleNormals.size());
      g.triangleNormals.push_back({f4(t.n[0]), f4(t.n[1]), f4(t.n[2])});
    }
    g.triangles.push_back(gt);
  }
  g.spheres.reserve(scene.spheres.size());
  for (const Sphere& s : scene.spheres) {
    gpu::GpuSphere gs{};
    gs.objectFromWorld = gpu::mat4(s.objectFromWorld);
    gs.centerRadius = f4(s.center, static_cast<float>(s.radius));
    gs.materialIndex = s.material;
    g.spheres.push_back(gs);
  }
  for (const Light& l : scene.lights) {
    gpu::GpuLight gl{};
    gl.positionOrDirection = f4(l.vec, l.type == LightType::Point ? gpu::kPointLight : 0.0f);
    gl.color = f4(l.color);
    gl.attenuation = f4(l.attenuation);
    g.lights.push_back(gl);
  }
  for (const Material& m : scene.materials) {
    g.materials.push_back({f4(m.ambient), f4(m.diffuse), f4(m.specular, static_cast<float>(m.shininess)),
                           f4(m.emission)});
  }
  g.bvh = buildBvh(scene);
  return g;
}

}  // namespace vkrt
