// gpu_types.h: every struct and constant the GPU shares with the host, valid C++20 (host/)
// and GLSL 450 (shaders/), in parts:
//   gpu_prelude.h   the macros that make one text both languages
//   gpu_limits.h    secondary-ray offsets, workgroup, step budget, leaf and stack sizes
//   gpu_scene.h     the scene's layouts (triangles, spheres, lights, materials, BVH, emitters)
//   gpu_rng.h       the path integrators' random numbers
//   gpu_render.h    what both shaders share: bindings, specialization ids, camera, parameters, traversal state
//   gpu_whitted.h   raytrace.comp's own interface
//   gpu_path.h      pathtrace.comp's own interface
#ifndef VKRT_GPU_TYPES_H
#define VKRT_GPU_TYPES_H

#include "gpu_limits.h"
#include "gpu_scene.h"
#include "gpu_rng.h"
#include "gpu_render.h"
#include "gpu_whitted.h"
#include "gpu_path.h"

#endif  // VKRT_GPU_TYPES_H
