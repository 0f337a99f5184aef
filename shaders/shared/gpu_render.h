// gpu_render.h: what both compute shaders share with the host: bindings, specialization ids,
// the state machine's phases, the camera, the render's parameters, the counters, and the
// traversal state that a suspended invocation saves (traverse.glsl).
#ifndef VKRT_GPU_RENDER_H
#define VKRT_GPU_RENDER_H

#include "gpu_limits.h"
#include "gpu_scene.h"

GPU_BEGIN

// Descriptor bindings (set 0) of both shaders: the scene, the band's pixels and states, the
// counters and the render's parameters (pathtrace.comp adds its own: gpu_path.h). The
// shapes' arrays come first (gpu_scene.h: kBindingTriangles ..), so that a shape adds its
// binding there without renumbering these.
GPU_CONST uint kBindingLights = kBindingShapesEnd + 0u;
GPU_CONST uint kBindingMaterials = kBindingShapesEnd + 1u;
GPU_CONST uint kBindingBvhNodes = kBindingShapesEnd + 2u;
GPU_CONST uint kBindingPrimRefs = kBindingShapesEnd + 3u;
GPU_CONST uint kBindingPixels = kBindingShapesEnd + 4u;       // output: one vec4 per pixel of the band, rgb = linear radiance, w = 1 when done (0: suspended)
GPU_CONST uint kBindingPathStates = kBindingShapesEnd + 5u;   // suspended state: a GpuWhittedState per invocation (raytrace.comp) or per pixel of the band (pathtrace.comp)
GPU_CONST uint kBindingCounters = kBindingShapesEnd + 6u;     // GpuCounters
GPU_CONST uint kBindingParams = kBindingShapesEnd + 7u;       // GpuRenderParams (a storage buffer: params.glsl)
GPU_CONST uint kBindingCount = kBindingShapesEnd + 8u;

// Specialization constant ids both shaders give the same meaning. Only what changes the code is specialised: what the scene
// contains (1) or not (0), so that the driver compiles out the code of absent features (and
// the Whitted shader's exactness cut-off, the path integrators' settings). Sizes, counts and loop bounds are data (GpuRenderParams): a new
// image size or triangle count is then no new shader for the driver to compile.
GPU_CONST uint kSpecHasTriangles = 0u;
GPU_CONST uint kSpecHasSpheres = 1u;
GPU_CONST uint kSpecHasSmoothNormals = 2u;   // `trinormal`
GPU_CONST uint kSpecHasPointLights = 3u;
GPU_CONST uint kSpecHasDirectionalLights = 4u;
GPU_CONST uint kSpecHasAttenuation = 5u;     // a point light whose attenuation is not 1 0 0
// 1: a ray is tested against every primitive, triangles then spheres (GpuRenderParams
// triangleCount and sphereCount), in a loop whose index is the same in every lane, instead of
// a walk of the BVH (traverse.glsl, traceRay); for scenes of at most kTestAllMaxPrims
// primitives (a sphere counting as two), each of them in the BVH and each a triangle or a
// sphere (a scene with a shape of another kind walks the BVH).
GPU_CONST uint kSpecTestAll = 6u;
// 1: the BVH's interior nodes hold blocks of four children (scene/wide_bvh.h), walked four
// boxes at a time (traverse.glsl); 0: two. Set in the general variant too (it follows the
// upload, not the scene's contents): chosen by --bvh, binary unless told (bench/README.md,
// "Tried and not kept").
GPU_CONST uint kSpecWideBvh = 7u;
GPU_CONST uint kSpecSharedCount = 8u;        // each shader's own ids follow (gpu_whitted.h, gpu_path.h)

// Phases of a pixel's state machine.
GPU_CONST uint kPhaseTrace = 0u;     // nearest hit of the current ray (camera or mirror)
GPU_CONST uint kPhaseLight = 1u;     // start the next light's shadow ray
GPU_CONST uint kPhaseShadow = 2u;    // any hit of the shadow ray
GPU_CONST uint kPhaseDone = 3u;     // the lane's last pixel is written (driver.glsl)
GPU_CONST uint kPhaseEnd = 4u;      // the path (a pixel's, or a sample's) is over: endPath (within a step, never saved)

// The camera in the float32 frame, as both shaders take it (camera.glsl).
struct GpuCamera {
  vec4 origin;              // xyz = look-from, w unused
  vec4 right;               // xyz = u * tan(fovx/2) / (W/2): one pixel to the right
  vec4 up;                  // xyz = v * tan(fovy/2) / (H/2): one pixel up
  vec4 back;                // xyz = w = normalize(from - at)
};
GPU_ASSERT_SIZE(GpuCamera, 64)

// What one render's dispatches share, besides the scene: sizes, counts and loop bounds. Data,
// not specialization constants, so that every scene with the same features runs one shader.
struct GpuRenderParams {
  uint width;               // the pixels computed (the whole image, or the --crop rectangle)
  uint height;
  uint maxDepth;            // mirror reflections at most (0 when no surface is specular)
  uint lightCount;
  uint stepBudget;          // state-machine steps per invocation per dispatch (kDefaultStepBudget)
  uint bandHeight;          // rows per band, a multiple of kWorkgroupSize
  uint tilesX;              // 8x8 tiles across the image (pathtrace.comp)
  uint tileOrderStride;     // coprime with the tiles of a band: the order workgroups visit them (pathtrace.comp)
  uint primCount;           // primitive references in the BVH; 0: no geometry (the root is an empty leaf)
  uint rootEntry;           // the root as a traversal-stack entry (gpu_scene.h)
  // A crop computes only the pixels [originX, originX + width) x [originY, originY + height)
  // of the full image; camera rays use the full image's size and pixel coordinates
  // (doc/scene-format.md, "Camera"), so a crop's pixels are those of a full render. The
  // whole image: origin 0 0, full size = width x height.
  uint originX;
  uint originY;
  uint fullWidth;
  uint fullHeight;
  uint triangleCount;       // the scene's triangles and spheres (read with kSpecTestAll)
  uint sphereCount;         // size 64 (std430)
};
GPU_ASSERT_SIZE(GpuRenderParams, 64)
GPU_ASSERT_OFFSET(GpuRenderParams, stepBudget, 16)
GPU_ASSERT_OFFSET(GpuRenderParams, rootEntry, 36)
GPU_ASSERT_OFFSET(GpuRenderParams, originX, 40)
GPU_ASSERT_OFFSET(GpuRenderParams, fullHeight, 52)
GPU_ASSERT_OFFSET(GpuRenderParams, sphereCount, 60)

struct GpuCounters {
  uint suspended;           // invocations (raytrace.comp) or pixels (pathtrace.comp) of this dispatch that ran out of steps
  uint shadowRays;
  uint secondaryRays;       // mirror (raytrace.comp) or scattered (pathtrace.comp) rays
  uint nonFinite;           // pixels whose radiance was NaN or infinite (RayCounts::nonFinite)
  // Pixels (raytrace.comp) or pixel samples (pathtrace.comp) finished in this dispatch: the
  // progress bar moves with every dispatch, not only with every band.
  uint finished;
  uint steps;               // state-machine steps (the path renderer sizes its bands by their speed)
  // The BVH walk's work (traverse.glsl; not counted where rays test every primitive): the
  // child boxes tested (two a node entered) and the primitives tested in the leaves, each a
  // 64-bit count as its low and high words (a GPU's dispatch may pass 2^32).
  uint boxTestsLow, boxTestsHigh;
  uint primitiveTestsLow, primitiveTestsHigh;
  uint pad0, pad1;          // size 48
};
GPU_ASSERT_SIZE(GpuCounters, 48)
GPU_ASSERT_OFFSET(GpuCounters, boxTestsLow, 24)
GPU_ASSERT_OFFSET(GpuCounters, primitiveTestsHigh, 36)

// What both compute shaders save of a suspended traversal (traverse.glsl): the current ray and
// its nearest hit so far, the shaded hit and the shadow ray leaving it, the phase of the state
// machine and the traversal stack with each entry's distance (so that a resumed traversal is
// the same as one that was never suspended).
struct GpuTraceState {
  vec4 origin;              // current ray (camera, mirror or scattered): xyz origin, w = tMin
  vec4 direction;           // xyz unit direction, w = nearest t so far
  vec4 hitPoint;            // xyz of the shaded hit, w = the offset of its secondary rays
  vec4 hitNormal;           // xyz unit shading normal, w = kGrazingPerMagnitude * the hit's magnitude
  vec4 shadowDir;           // xyz shadow ray direction, w = its tMax
  float hitB1, hitB2;       // barycentric weights of p1 and p2 of the nearest hit so far (triangles)
  float shadowCos;          // N . shadowDir at the shaded hit
  uint phase;               // kPhaseTrace, kPhaseLight or kPhaseShadow
  uint hitPrim;             // primRef of the nearest hit so far, or kNoHit
  uint hitMaterial;         // of the shaded hit
  uint lightIndex;          // the shader's next light (raytrace.comp) or light sample (pathtrace.comp)
  uint stackSize;           // size 112
  uint stack[kTraversalStackSize];
  float stackT[kTraversalStackSize];
};
GPU_ASSERT_SIZE(GpuTraceState, 112 + 8 * 96)
GPU_ASSERT_OFFSET(GpuTraceState, phase, 92)
GPU_ASSERT_OFFSET(GpuTraceState, stack, 112)
GPU_ASSERT_OFFSET(GpuTraceState, stackT, 112 + 4 * 96)

GPU_CONST uint kNoHit = 0xFFFFFFFFu;

GPU_END
#endif  // VKRT_GPU_RENDER_H
