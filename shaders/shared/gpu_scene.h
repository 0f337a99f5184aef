// gpu_scene.h: the scene as the GPU reads it (flatten() writes it, scene_reads.glsl and
// shaders/shapes/ read it): primitive references, each shape's kind, binding and layout
// (triangles, spheres), lights, materials, quad lights, BVH nodes and their stack entries, and
// the emitter table.
#ifndef VKRT_GPU_SCENE_H
#define VKRT_GPU_SCENE_H

#include "gpu_prelude.h"

GPU_BEGIN

// A BVH leaf's primitive reference: the primitive's kind in the top bits, its index in that
// kind's array below them (room for eight kinds of 2^29 primitives each).
GPU_CONST uint kPrimKindShift = 29u;
GPU_CONST uint kPrimIndexMask = 0x1FFFFFFFu;
GPU_CONST uint kPrimTriangle = 0u;
GPU_CONST uint kPrimSphere = 1u;
// Each shape's arrays are the first bindings (set 0) of both shaders; gpu_render.h numbers the
// rest from kBindingShapesEnd.
GPU_CONST uint kBindingTriangles = 0u;
GPU_CONST uint kBindingTriangleNormals = 1u;
GPU_CONST uint kBindingSpheres = 2u;
GPU_CONST uint kBindingShapesEnd = 3u;
GPU_FN uint primRef(uint kind, uint index) { return (kind << kPrimKindShift) | index; }
GPU_FN uint primKind(uint ref) { return ref >> kPrimKindShift; }
GPU_FN uint primIndex(uint ref) { return ref & kPrimIndexMask; }
// GpuTriangle.normalsIndex of a flat triangle (face normal).
GPU_CONST uint kNoNormals = 0xFFFFFFFFu;
// GpuLight.kind: the light's type, in the order of host/scene/light.h's list (VKRT_LIGHT_TYPES).
GPU_CONST uint kLightPoint = 0u;
GPU_CONST uint kLightDirectional = 1u;

// std430, and only vec4/mat4/uint/float members: a vec3 lives in a vec4 whose .w holds a
// scalar that belongs with it, and named pad fields bring each struct to a multiple of 16.

struct GpuTriangle {        // scene-centred frame (flatten()), counter-clockwise
  vec4 p0;                  // xyz = vertex 0, w = x of the unit face normal N
  vec4 p1;                  // xyz = vertex 1, w = N.y
  vec4 p2;                  // xyz = vertex 2, w = N.z (N = 0 for a degenerate triangle)
  uint materialIndex;
  uint normalsIndex;        // into the GpuTriangleNormals array, or kNoNormals
  float rayOffset;          // secondary rays leaving it ignore hits closer than this (gpu_limits.h)
  float planeOffset;        // dot(N, p) for the points p of its plane (computed in double)
};
GPU_ASSERT_SIZE(GpuTriangle, 64)
GPU_ASSERT_OFFSET(GpuTriangle, materialIndex, 48)
GPU_ASSERT_OFFSET(GpuTriangle, normalsIndex, 52)
GPU_ASSERT_OFFSET(GpuTriangle, rayOffset, 56)
GPU_ASSERT_OFFSET(GpuTriangle, planeOffset, 60)

struct GpuTriangleNormals { // unit normals at the three vertices (`trinormal`)
  vec4 n0;
  vec4 n1;
  vec4 n2;
};
GPU_ASSERT_SIZE(GpuTriangleNormals, 48)

struct GpuSphere {          // an ellipsoid: the sphere (center, radius) under a transform
  mat4 objectFromWorld;     // inverse of the transform current at the `sphere` line
  vec4 centerRadius;        // xyz = center in object space, w = radius
  uint materialIndex;
  float rayOffset;          // secondary rays leaving it ignore hits closer than this (gpu_limits.h)
  uint pad0, pad1;          // array stride 96
};
GPU_ASSERT_SIZE(GpuSphere, 96)
GPU_ASSERT_OFFSET(GpuSphere, centerRadius, 64)
GPU_ASSERT_OFFSET(GpuSphere, materialIndex, 80)
GPU_ASSERT_OFFSET(GpuSphere, rayOffset, 84)

struct GpuLight {
  vec4 positionOrDirection; // scene-centred frame: a point light's position, or the unit direction toward a directional light; w unused
  vec4 color;               // rgb, w unused
  // The attenuation divisor c0 + c1 d + c2 d^2 (point lights; 1 0 0 for the others), d in the frame's units.
  float attenuation0;
  float attenuation1;
  float attenuation2;
  uint kind;                // kLightPoint or kLightDirectional
};
GPU_ASSERT_SIZE(GpuLight, 48)
GPU_ASSERT_OFFSET(GpuLight, attenuation0, 32)
GPU_ASSERT_OFFSET(GpuLight, kind, 44)
GPU_CONST uint kLightTexels = 3u;   // RGBA32UI texels of one GpuLight (texel-buffer reads)

struct GpuMaterial {
  vec4 ambient;             // rgb, w = the BRDF model: kBrdfPhong or kBrdfGgx (path integrators)
  vec4 diffuse;             // rgb, w = GGX roughness (alpha, unsquared)
  vec4 specular;            // rgb, w = shininess
  vec4 emission;            // rgb, w = the quad light these triangles make (index), or kNoQuadLight
};
GPU_ASSERT_SIZE(GpuMaterial, 64)
GPU_ASSERT_OFFSET(GpuMaterial, specular, 32)

GPU_CONST float kBrdfPhong = 0.0f;
GPU_CONST float kBrdfGgx = 1.0f;
GPU_CONST float kNoQuadLight = -1.0f;   // GpuMaterial.emission.w of a surface that is no quad light

// `quadLight` (doc/path-tracing.md, "Quad lights"), in the scene-centred frame: the parallelogram
// a + u ab + v ac, u, v in [0, 1], emitting `radiance` on the side of n = normalize(cross(ac, ab)).
// Its two triangles are also in the triangle array, with a material whose emission.w names it.
struct GpuQuadLight {
  vec4 corner;              // xyz = a, w = area |cross(ab, ac)|
  vec4 edgeAB;              // xyz = ab, w unused
  vec4 edgeAC;              // xyz = ac, w unused
  vec4 normal;              // xyz = n, w unused
  vec4 radiance;            // rgb = L, w unused
};
GPU_ASSERT_SIZE(GpuQuadLight, 80)
GPU_CONST uint kQuadLightTexels = 5u;   // RGBA32UI texels of one GpuQuadLight (texel-buffer reads)

struct GpuBvhNode {         // axis-aligned box, rounded outward to float
  float minX, minY, minZ;
  uint leftOrFirst;         // interior: index of the left child (right = left + 1); leaf: first primRef
  float maxX, maxY, maxZ;
  uint primCount;           // 0 for an interior node
};
GPU_ASSERT_SIZE(GpuBvhNode, 32)
GPU_ASSERT_OFFSET(GpuBvhNode, leftOrFirst, 12)
GPU_ASSERT_OFFSET(GpuBvhNode, primCount, 28)

// A traversal-stack entry says what its parent's read of the node told: for a leaf,
// kStackLeafBit | count << kStackCountShift | first primRef (first < 2^28, count <= 7); for an
// interior node, the index of its left child. Popping it needs no read of the node.
GPU_CONST uint kStackLeafBit = 0x80000000u;
GPU_CONST uint kStackCountShift = 28u;
GPU_CONST uint kStackFirstMask = 0x0FFFFFFFu;

// An emissive triangle or sphere that next-event estimation samples (the rules:
// doc/design.md, "Random numbers and sampling rules"; the table: host/scene/emitters.h). A sample picks
// entry e with probability cdf[e] - cdf[e - 1]; that is weight / total, weight = area x
// sum(|emission|), so the density per world area of the point it draws, pick x area pdf, is
// sum(|emission|) / total on a triangle, and on an ellipsoid
// sum(|emission|) / total / (|det M|^(1/3) |M^-T n|) (its area counted as 4 pi r^2 |det M|^(2/3)).
struct GpuEmitter {
  uint primRef;             // primRef(kind, index)
  float cdf;                // cumulative pick probability up to and with this entry (the last is 1)
};
GPU_ASSERT_SIZE(GpuEmitter, 8)
GPU_ASSERT_OFFSET(GpuEmitter, cdf, 4)

GPU_END
#endif  // VKRT_GPU_SCENE_H
