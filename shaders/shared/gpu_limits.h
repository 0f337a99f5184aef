// gpu_limits.h: the numbers both backends and both shaders keep to: the secondary-ray
// offsets, the workgroup, the step budget of the state machines, leaf and stack sizes.
#ifndef VKRT_GPU_LIMITS_H
#define VKRT_GPU_LIMITS_H

#include "gpu_prelude.h"

GPU_BEGIN

// Secondary rays (shadow, mirror, scattered) start at the hit point p and ignore hits with
//     t <= max(rayOffset, kOffsetPerMagnitude * m, kGrazingPerMagnitude * m / |N.dir|),
//     m = max(|p - o|_max, |p - camera|_max),
// in the float32 frame of flatten() (o its origin), rayOffset being the hit primitive's
// (GpuTriangle, GpuSphere; host/scene/ray_offset.cpp). The primary ray takes every hit with
// t > 0. The policy and its reasons: doc/design.md, "The secondary-ray offsets".
GPU_CONST float kSecondaryRayTMin = 1e-3f;   // the course's (doc/scene-format.md, "Conventions")
GPU_CONST float kCourseSizeLow = 0.25f;   // the band of object sizes that keep 1e-3
GPU_CONST float kCourseSizeHigh = 60.0f;
GPU_CONST float kOffsetPerMagnitude = 3.814697265625e-6f;   // 2^-18: 32 ulps of float32
GPU_CONST float kGrazingPerMagnitude = 4.76837158203125e-7f;   // 2^-21: 8 ulps of float32

GPU_CONST uint kWorkgroupSize = 8u;       // 8x8 pixels per workgroup (lavapipe: 8 wide or more)

// llvmpipe ends a shader invocation silently after 65,535 loop iterations in all. One step
// of the shader's state machine runs at most 1 + kMaxLeafPrims loop iterations, so a budget
// of this many steps per dispatch stays well inside the limit; an invocation (raytrace.comp)
// or pixel (pathtrace.comp) that needs more is suspended (its GpuWhittedState or GpuPathTracerState saved) and resumed
// by the next dispatch.
GPU_CONST uint kDefaultStepBudget = 8192u;
GPU_CONST uint kMaxLeafPrims = 4u;
// The shaders' test of every primitive (kSpecTestAll) is for scenes of at most this many
// primitives, a sphere counting as two triangles (its test reads 6 texels and transforms the
// ray); it counts as one step per kMaxLeafPrims of them. The walk of the BVH wins from about
// 45 (bench/README.md, "Path tracing on lavapipe" and "Every primitive tested").
GPU_CONST uint kTestAllMaxPrims = 45u;
// raytrace.comp: each workgroup takes a run of this many 8x8 tiles of a band, each lane a
// pixel of each tile in turn, a new one when its pixel is done (VulkanOptions::pixelsPerInvocation;
// on CPU devices: a GPU gets a pixel per invocation).
GPU_CONST uint kDefaultPixelsPerInvocation = 16u;
// Entries of the shader's traversal stack and of a saved one: the BVH builder bounds the
// depth so that depth + 1 entries never exceed this (kMaxBvhDepth, host/scene/bvh.h).
GPU_CONST uint kTraversalStackSize = 96u;

GPU_END
#endif  // VKRT_GPU_LIMITS_H
