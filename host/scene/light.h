// The point and directional lights (doc/scene-format.md, "Lights"): what the scene holds of
// one, what reaches a point from it (both CPU references ask here), its GPU layout
// (flatten() asks here), and the most it can send (the exactness cut-off's bound). Its
// shader side is shaders/lights.glsl. A new type of light adds its row to VKRT_LIGHT_TYPES, its
// kind in gpu_scene.h and a case in each switch of light.cpp; the compiler lists what it misses.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace vkrt {

// The light types, once: X(Type, command name, GPU kind), in the order in which `--stats`
// lists them. LightType, kLightTypeNames and the GPU kind (GpuLight.kind) come from here.
#define VKRT_LIGHT_TYPES(X)                  \
  X(Point, "point", gpu::kLightPoint)        \
  X(Directional, "directional", gpu::kLightDirectional)

#define VKRT_LIGHT_ENUM(Type, name, kind) Type,
enum class LightType { VKRT_LIGHT_TYPES(VKRT_LIGHT_ENUM) };
#undef VKRT_LIGHT_ENUM
#define VKRT_LIGHT_COUNT(Type, name, kind) +1
inline constexpr std::size_t kLightTypeCount = 0 VKRT_LIGHT_TYPES(VKRT_LIGHT_COUNT);
#undef VKRT_LIGHT_COUNT
// Each type's command name, in the order of the enum.
#define VKRT_LIGHT_NAME(Type, name, kind) name,
inline constexpr std::array<std::string_view, kLightTypeCount> kLightTypeNames = {VKRT_LIGHT_TYPES(VKRT_LIGHT_NAME)};
#undef VKRT_LIGHT_NAME
// The type's GpuLight.kind.
constexpr std::uint32_t gpuKindOf(LightType type) {
#define VKRT_LIGHT_KIND(Type, name, kind) kind,
  constexpr std::uint32_t kinds[] = {VKRT_LIGHT_TYPES(VKRT_LIGHT_KIND)};
#undef VKRT_LIGHT_KIND
  return kinds[static_cast<std::size_t>(type)];
}

struct Light {
  LightType type = LightType::Directional;
  glm::dvec3 vec{0.0};                // point: world position; directional: unit world direction toward the light
  glm::dvec3 color{0.0};
  glm::dvec3 attenuation{1, 0, 0};    // constant, linear, quadratic; used by point lights only
};

// What reaches point p from a light: the unit direction toward it, how far a shadow ray goes
// (infinity for a directional light), and the divisor of its colour (the attenuation
// c0 + c1 d + c2 d^2 of doc/scene-format.md, "Shading"; 1 without one).
struct LightArrival {
  glm::dvec3 toLight{0.0};
  double distance = 0.0;
  double divisor = 1.0;
};
// False when p is where the light is (no direction): it lights nothing there.
bool arrivalAt(const Light& light, const glm::dvec3& p, LightArrival& arrival);

// The light in the float32 frame of flatten() (origin, power-of-two scale). A point light so
// far that float32 cannot place it is moved nearer along the same line, its colour divided by
// its attenuation there.
gpu::GpuLight toGpu(const Light& light, const glm::dvec3& origin, double scale);

// The largest 1 / divisor the light has at any distance (infinity when the divisor can come
// near 0), and whether its arriving colour keeps the sign of its colour.
double strongestDivisorInverse(const Light& light, bool& keepsSign);

}  // namespace vkrt
