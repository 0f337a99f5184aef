// gpu_types.h: every struct the GPU reads, shared by C++ (host/) and GLSL (shaders/).
// Must stay valid C++20 and valid GLSL 450: no templates, no methods, no ';' after a macro.
#ifndef VKRT_GPU_TYPES_H
#define VKRT_GPU_TYPES_H

#ifdef __cplusplus
#  include <cstddef>
#  include <cstdint>
#  include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#  define GPU_CONST inline constexpr
#  define GPU_ASSERT_SIZE(T, n) static_assert(sizeof(T) == (n), #T " size drifted");
#  define GPU_ASSERT_OFFSET(T, m, n) static_assert(offsetof(T, m) == (n), #T "." #m " moved");
#else
#  define GPU_CONST const
#  define GPU_ASSERT_SIZE(T, n)
#  define GPU_ASSERT_OFFSET(T, m, n)
#endif

// Secondary rays (shadow and mirror) start at the hit point and ignore hits with t at or
// below this distance, in scene units along a unit direction (SPEC section 7). This is the
// one place that states the policy; both backends read it from here.
GPU_CONST float kSecondaryRayTMin = 1e-3f;

// A BVH leaf's primitive reference: triangle index, or sphere index with this bit set.
GPU_CONST uint kPrimSphereBit = 0x80000000u;
// GpuTriangle.normalsIndex of a flat triangle (face normal).
GPU_CONST uint kNoNormals = 0xFFFFFFFFu;
// GpuLight.positionOrDirection.w: 1 for a point light, 0 for a directional one.
GPU_CONST float kPointLight = 1.0f;

// std430, and only vec4/mat4/uint/float members: a vec3 lives in a vec4 whose .w holds a
// scalar that belongs with it, and named pad fields bring each struct to a multiple of 16.

struct GpuTriangle {        // world space, counter-clockwise
  vec4 p0;                  // xyz = vertex 0, w unused (0)
  vec4 p1;                  // xyz = vertex 1, w unused (0)
  vec4 p2;                  // xyz = vertex 2, w unused (0)
  uint materialIndex;
  uint normalsIndex;        // into the GpuTriangleNormals array, or kNoNormals
  uint pad0, pad1;          // array stride 64
};
GPU_ASSERT_SIZE(GpuTriangle, 64)
GPU_ASSERT_OFFSET(GpuTriangle, materialIndex, 48)
GPU_ASSERT_OFFSET(GpuTriangle, normalsIndex, 52)

struct GpuTriangleNormals { // world-space unit normals at the three vertices (`trinormal`)
  vec4 n0;
  vec4 n1;
  vec4 n2;
};
GPU_ASSERT_SIZE(GpuTriangleNormals, 48)

struct GpuSphere {          // an ellipsoid: the sphere (center, radius) under a transform
  mat4 objectFromWorld;     // inverse of the transform current at the `sphere` line
  vec4 centerRadius;        // xyz = center in object space, w = radius
  uint materialIndex;
  uint pad0, pad1, pad2;    // array stride 96
};
GPU_ASSERT_SIZE(GpuSphere, 96)
GPU_ASSERT_OFFSET(GpuSphere, centerRadius, 64)
GPU_ASSERT_OFFSET(GpuSphere, materialIndex, 80)

struct GpuLight {
  vec4 positionOrDirection; // world space; w = kPointLight (point) or 0 (direction toward light)
  vec4 color;               // rgb, w unused
  vec4 attenuation;         // xyz = constant, linear, quadratic (point lights), w unused
};
GPU_ASSERT_SIZE(GpuLight, 48)

struct GpuMaterial {
  vec4 ambient;             // rgb, w unused
  vec4 diffuse;             // rgb, w unused
  vec4 specular;            // rgb, w = shininess
  vec4 emission;            // rgb, w unused
};
GPU_ASSERT_SIZE(GpuMaterial, 64)
GPU_ASSERT_OFFSET(GpuMaterial, specular, 32)

struct GpuBvhNode {         // axis-aligned box, rounded outward to float
  float minX, minY, minZ;
  uint leftOrFirst;         // interior: index of the left child (right = left + 1); leaf: first primRef
  float maxX, maxY, maxZ;
  uint primCount;           // 0 for an interior node
};
GPU_ASSERT_SIZE(GpuBvhNode, 32)
GPU_ASSERT_OFFSET(GpuBvhNode, leftOrFirst, 12)
GPU_ASSERT_OFFSET(GpuBvhNode, primCount, 28)

#ifdef __cplusplus
}  // namespace gpu
#endif
#endif  // VKRT_GPU_TYPES_H
