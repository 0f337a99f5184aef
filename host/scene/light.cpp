// The point and directional lights: what reaches a point, the GPU layout, the strongest arrival.
// (A new type of light: a case in each switch here.)
#include "scene/light.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/unit_vector.h"

namespace vkrt {
namespace {

constexpr double kFloatMax = std::numeric_limits<float>::max();
// A point light farther than this from the frame's origin (max norm, frame units) is moved
// to this distance (toGpu).
constexpr double kFarLight = 0x1p40;

gpu::vec4 f4(const glm::dvec3& v, float w = 0.0f) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), w};
}

// Sets the light's attenuation divisor c0 + c1 r + c2 r^2.
void setAttenuation(gpu::GpuLight& gl, const glm::dvec3& c) {
  gl.attenuation0 = static_cast<float>(c.x);
  gl.attenuation1 = static_cast<float>(c.y);
  gl.attenuation2 = static_cast<float>(c.z);
}

}  // namespace

bool arrivalAt(const Light& light, const glm::dvec3& p, LightArrival& arrival) {
  switch (light.type) {
    case LightType::Point: {
      const glm::dvec3 v = light.vec - p;
      arrival.distance = lengthOf(v);
      if (arrival.distance == 0.0) return false;
      arrival.toLight = v / arrival.distance;
      const double d = arrival.distance;
      arrival.divisor = light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d;
      return true;
    }
    case LightType::Directional:
      arrival.toLight = light.vec;
      arrival.distance = std::numeric_limits<double>::infinity();
      arrival.divisor = 1.0;
      return true;
  }
  return false;
}

gpu::GpuLight toGpu(const Light& l, const glm::dvec3& origin, double scale) {
  gpu::GpuLight gl{};
  gl.color = f4(l.color);
  gl.kind = gpuKindOf(l.type);
  setAttenuation(gl, glm::dvec3(1.0, 0.0, 0.0));
  switch (l.type) {
    case LightType::Directional:
      gl.positionOrDirection = f4(l.vec);
      break;
    case LightType::Point: {
      const glm::dvec3 position = (l.vec - origin) * scale;
      gl.positionOrDirection = f4(position);
      // The divisor c0 + c1 r + c2 r^2 with r in the frame's units; a coefficient beyond float
      // is the largest float (the light is then as good as 0 wherever r is not).
      const glm::dvec3& c = l.attenuation;
      setAttenuation(gl, glm::min(glm::dvec3(c.x, c.y / scale, c.z / scale / scale), glm::dvec3(kFloatMax)));
      const double far = std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)});
      if (far > kFarLight) {
        // So far beyond the geometry (whose frame coordinates are at most a few units) that its
        // direction and distance are the same from every point of it, to far below float32's
        // resolution (2^-39): moved to kFarLight along the same line, its colour divided by the
        // attenuation at its distance in double (float32 would overflow squaring that distance).
        const glm::dvec3 unit = unitVector(position);
        const double distance = glm::dot(position * (1.0 / far), unit) * far / scale;   // in world units
        const double divisor = c.x + c.y * distance + c.z * distance * distance;
        gl.positionOrDirection = f4(unit * kFarLight);
        gl.color = f4(glm::clamp(l.color / divisor, glm::dvec3(-kFloatMax), glm::dvec3(kFloatMax)));
        setAttenuation(gl, glm::dvec3(1.0, 0.0, 0.0));
      }
      break;
    }
  }
  return gl;
}

double strongestDivisorInverse(const Light& l, bool& keepsSign) {
  keepsSign = true;
  switch (l.type) {
    case LightType::Directional: return 1.0;
    case LightType::Point: {
      const glm::dvec3& a = l.attenuation;
      // c0 + c1 r + c2 r^2 >= c0 > 0 for every distance r when no term is negative; a
      // negative term can also make the light negative.
      keepsSign = a.x >= 0.0 && a.y >= 0.0 && a.z >= 0.0;
      return a.x > 0.0 && a.y >= 0.0 && a.z >= 0.0 ? 1.0 / a.x : std::numeric_limits<double>::infinity();
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace vkrt
