// The scene description: what a .test file says, in world space and double precision.
// Produced by the parser, read by flatten() and the CPU reference. Knows nothing of Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkrt {

using glm::dmat4;
using glm::dvec3;

struct Material {
  dvec3 ambient{0.2, 0.2, 0.2};
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};
  dvec3 emission{0.0};
  double shininess = 0.0;
  bool operator==(const Material&) const = default;
};

struct Triangle {       // world space, counter-clockwise
  dvec3 p[3];
  dvec3 n[3];           // world-space unit vertex normals; meaningful only when smooth
  bool smooth = false;  // `trinormal`: normals interpolated barycentrically
  std::uint32_t material = 0;
};

struct Sphere {         // (center, radius) in object space, under worldFromObject
  dmat4 worldFromObject{1.0};
  dmat4 objectFromWorld{1.0};
  dvec3 center{0.0};
  double radius = 1.0;
  std::uint32_t material = 0;
};

enum class LightType { Directional, Point };

struct Light {
  LightType type = LightType::Directional;
  dvec3 vec{0.0};                // point: world position; directional: world direction toward the light
  dvec3 color{0.0};
  dvec3 attenuation{1, 0, 0};    // constant, linear, quadratic; used by point lights only
};

struct Camera {
  dvec3 from{0.0}, at{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
  double fovyDegrees = 45.0;
};

struct SceneDesc {
  std::string sourcePath;        // the file as named by the user (for messages)
  int width = 0, height = 0;
  int sizeLine = 0;              // line of the `size` command
  int maxDepth = 5;              // primary hit plus up to maxDepth mirror reflections
  std::string output = "raytrace.png";
  int outputLine = 0;            // line of the `output` command, 0 when defaulted
  Camera camera;
  std::vector<Material> materials;
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<Light> lights;
};

}  // namespace vkrt
