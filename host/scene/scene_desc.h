// The scene description: what a .test file says, in world space and double precision.
// Produced by the parser, read by flatten() and the CPU reference. Knows nothing of Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/integrator_table.h"
#include "scene/light.h"
#include "scene/shapes/shape_list.h"

namespace vkrt {

using glm::dmat4;
using glm::dvec3;

// doc/path-tracing.md, "Commands": the path integrators' settings (the algorithm, Integrator:
// integrator_table.h).
enum class NextEvent { Off, On, Mis };
enum class Sampling { Hemisphere, Cosine, Brdf };
// Their keywords (`nexteventestimation`, `importancesampling`), in the enums' order.
inline constexpr std::string_view kNextEventNames[] = {"off", "on", "mis"};
inline constexpr std::string_view kSamplingNames[] = {"hemisphere", "cosine", "brdf"};
enum class BrdfModel { Phong, Ggx };

struct Material {
  dvec3 ambient{0.2, 0.2, 0.2};
  dvec3 diffuse{0.0};
  dvec3 specular{0.0};
  dvec3 emission{0.0};
  double shininess = 0.0;
  BrdfModel brdf = BrdfModel::Phong;   // `brdf` (path integrators only)
  double roughness = 0.0;              // `roughness`: GGX alpha, used unsquared
  // The quad light (index into SceneDesc::quadLights) whose two triangles have this material:
  // they emit that light's radiance on its front side only, and are black otherwise. -1: none.
  int quadLight = -1;
  bool operator==(const Material&) const = default;
};

// `quadLight a ab ac L` (doc/path-tracing.md, "Quad lights"), world space: the parallelogram with
// corners a, a+ab, a+ab+ac, a+ac, emitting radiance L on the side of n = normalize(cross(ac, ab)).
// It is also geometry: two triangles of SceneDesc::triangles, wound so that their face normal
// is n, whose material has quadLight set to this light's index.
struct QuadLight {
  dvec3 a{0.0}, ab{0.0}, ac{0.0};
  dvec3 radiance{0.0};
  int line = 0;                  // the `quadLight` line (for messages)
};

// The path integrators' settings (doc/path-tracing.md, "Commands"; doc/path-tracing.md, "Estimators"); the defaults are the
// format's. Ignored by Integrator::Raytracer.
struct PathSettings {
  Integrator integrator = Integrator::Raytracer;
  int spp = 1;                   // camera samples per pixel
  int lightSamples = 1;          // per quad light per shading point
  int lightSamplesLine = 0;      // the last `lightsamples` line, 0 when defaulted (for messages)
  bool lightStratify = false;    // lightSamples is then a perfect square
  NextEvent nextEvent = NextEvent::Off;
  bool russianRoulette = false;
  Sampling sampling = Sampling::Hemisphere;
  double gamma = 1.0;            // output encoding: byte = floor(255 clamp(L^(1/gamma), 0, 1))
};

struct Camera {
  dvec3 from{0.0}, at{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
  double fovyDegrees = 45.0;
};

struct SceneDesc {
  std::string sourcePath;        // the file as named by the user (for messages)
  std::uint64_t sourceHash = 0;  // 64-bit FNV-1a of the text as parsed (a render's identity starts from it)
  int width = 0, height = 0;
  int sizeLine = 0;              // line of the `size` command
  // Raytracer: primary hit plus up to maxDepth mirror reflections. Path integrators: light
  // paths of at most maxDepth + 1 segments (doc/path-tracing.md, "Estimators"); -1 = no limit.
  int maxDepth = 5;
  std::string output = "raytrace.png";
  int outputLine = 0;            // line of the `output` command, 0 when defaulted
  Camera camera;
  std::vector<Material> materials;
  // Each shape's primitives (shapes/shape_list.h): `triangles`, `spheres`.
#define VKRT_SHAPE_MEMBER(Type, member, name, kind, GpuType, binding) std::vector<Type> member;
  VKRT_SHAPES(VKRT_SHAPE_MEMBER)
#undef VKRT_SHAPE_MEMBER
  std::vector<Light> lights;
  std::vector<QuadLight> quadLights;
  PathSettings path;
};

}  // namespace vkrt
