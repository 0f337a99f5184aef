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
#  define GPU_FN inline
#  define GPU_ASSERT_SIZE(T, n) static_assert(sizeof(T) == (n), #T " size drifted");
#  define GPU_ASSERT_OFFSET(T, m, n) static_assert(offsetof(T, m) == (n), #T "." #m " moved");
#else
#  define GPU_CONST const
#  define GPU_FN
#  define GPU_ASSERT_SIZE(T, n)
#  define GPU_ASSERT_OFFSET(T, m, n)
#endif

// ---- Secondary rays: the offset policy (the one place that states it) --------------------------
// The shader works in the float32 frame of flatten() (host/scene/ray_offset.h): centred on the
// scene's geometry, or on the camera when a far object would put that centre far from what
// it sees nearby, and scaled by a power of two that brings the scene's size near 1 (computed
// in double precision), so a scene far from the origin, vast or tiny, gives float32 the same
// numbers. rayOffset and every length below are in the frame's units.
// A secondary ray (shadow or mirror) starts at the hit point p and ignores hits with
//     t <= max(rayOffset, kOffsetPerMagnitude * m, kGrazingPerMagnitude * m / |N.dir|),
//     m = max(|p - o|_max, |p - camera|_max)
// along its unit direction (o: the frame's origin), where rayOffset belongs to
// the primitive that was hit (GpuTriangle, GpuSphere; host/scene/ray_offset.cpp):
//  - Objects: each sphere, and each set of triangles connected through shared vertex
//    positions (a mesh, a quad, a box). An object's size S is the diagonal of its box.
//  - An object's offset is the course's kSecondaryRayTMin (1e-3; doc/scene-format.md, "Conventions") when S is
//    within [kCourseSizeLow, kCourseSizeHigh], else 1e-3 * 10^k, k = the whole decades that
//    bring S into that band (negative for small objects). Under scaling by 10^k it scales
//    exactly for objects with S in [2.5, 6] (down) or [25, 60] (up), within 10x otherwise.
//  - A primitive's rayOffset is its object's, lowered to the smallest offset of any object
//    whose box comes within that distance of the primitive's box: a ray leaving a vast floor
//    where a small box stands on it ignores no more of the box than a ray leaving the box.
//    So one vast object (a quad scaled by 100, a ground plane 20,000 units wide) changes
//    nothing for the small objects on it, and the course's scenes keep 1e-3 everywhere.
//  - The second term, 32 float32 ulps of the hit point's magnitude in the float32 frame and
//    from the camera, keeps a ray off its own surface where float32 rounds p more coarsely
//    than rayOffset. For the course's scenes it is below 1e-3 (magnitudes < 260).
//  - The third, kGrazingPerMagnitude * magnitude / cos, with cos = |N.dir| against the
//    shading normal, keeps a ray that leaves nearly along the surface (a light 0.001 degrees
//    above a floor) from hitting that surface again: the float32 hit point may lie a few ulps
//    below it, and the ray crosses that depth only after depth / cos. For the course's scenes
//    it exceeds 1e-3 only for cos < 0.012 (within 0.7 degrees of grazing).
// The primary (camera) ray takes every hit with t > 0.
GPU_CONST float kSecondaryRayTMin = 1e-3f;
GPU_CONST float kCourseSizeLow = 0.25f;   // the band of object sizes that keep 1e-3
GPU_CONST float kCourseSizeHigh = 60.0f;
GPU_CONST float kOffsetPerMagnitude = 3.814697265625e-6f;   // 2^-18: 32 ulps of float32
GPU_CONST float kGrazingPerMagnitude = 4.76837158203125e-7f;   // 2^-21: 8 ulps of float32

// A BVH leaf's primitive reference: the primitive's kind in the top bits, its index in that
// kind's array below them (room for eight kinds of 2^29 primitives each).
GPU_CONST uint kPrimKindShift = 29u;
GPU_CONST uint kPrimIndexMask = 0x1FFFFFFFu;
GPU_CONST uint kPrimTriangle = 0u;
GPU_CONST uint kPrimSphere = 1u;
GPU_FN uint primRef(uint kind, uint index) { return (kind << kPrimKindShift) | index; }
GPU_FN uint primKind(uint ref) { return ref >> kPrimKindShift; }
GPU_FN uint primIndex(uint ref) { return ref & kPrimIndexMask; }
// GpuTriangle.normalsIndex of a flat triangle (face normal).
GPU_CONST uint kNoNormals = 0xFFFFFFFFu;
// GpuLight.positionOrDirection.w: 1 for a point light, 0 for a directional one.
GPU_CONST float kPointLight = 1.0f;

// std430, and only vec4/mat4/uint/float members: a vec3 lives in a vec4 whose .w holds a
// scalar that belongs with it, and named pad fields bring each struct to a multiple of 16.

struct GpuTriangle {        // scene-centred frame (flatten()), counter-clockwise
  vec4 p0;                  // xyz = vertex 0, w = x of the unit face normal N
  vec4 p1;                  // xyz = vertex 1, w = N.y
  vec4 p2;                  // xyz = vertex 2, w = N.z (N = 0 for a degenerate triangle)
  uint materialIndex;
  uint normalsIndex;        // into the GpuTriangleNormals array, or kNoNormals
  float rayOffset;          // secondary rays leaving it ignore hits closer than this (above)
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
  float rayOffset;          // secondary rays leaving it ignore hits closer than this (above)
  uint pad0, pad1;          // array stride 96
};
GPU_ASSERT_SIZE(GpuSphere, 96)
GPU_ASSERT_OFFSET(GpuSphere, centerRadius, 64)
GPU_ASSERT_OFFSET(GpuSphere, materialIndex, 80)
GPU_ASSERT_OFFSET(GpuSphere, rayOffset, 84)

struct GpuLight {
  vec4 positionOrDirection; // scene-centred frame; w = kPointLight (point) or 0 (direction toward light)
  vec4 color;               // rgb, w unused
  vec4 attenuation;         // xyz = constant, linear, quadratic (point lights), w unused
};
GPU_ASSERT_SIZE(GpuLight, 48)

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

// Path integrators (doc/path-tracing.md, "Integrators"); the ids the shader and the host share.
GPU_CONST uint kIntegratorRaytracer = 0u;
GPU_CONST uint kIntegratorAnalyticDirect = 1u;
GPU_CONST uint kIntegratorDirect = 2u;
GPU_CONST uint kIntegratorPathTracer = 3u;
GPU_CONST uint kNextEventOff = 0u;
GPU_CONST uint kNextEventOn = 1u;
GPU_CONST uint kNextEventMis = 2u;
GPU_CONST uint kSamplingHemisphere = 0u;
GPU_CONST uint kSamplingCosine = 1u;
GPU_CONST uint kSamplingBrdf = 2u;

// ---- Random numbers: a counter-based generator ------------------------------------------------
// The number for (seed, pixel, sample, dimension) is a hash of the four: a render is
// reproducible bit for bit whatever the order in which pixels and samples are computed, a
// crop draws the numbers of the full image (pixel = y * full width + x), sample batches of
// one render draw different numbers (sample counts from the render's first sample), and the
// CPU reference and the shader draw the same numbers for the same path.
// Dimensions: kRngPixelX/Y jitter the camera ray inside its pixel; each path vertex (bounce
// b = 0 at the primary hit) then uses b * kRngBounceStride + a slot:
GPU_CONST uint kRngPixelX = 0u;
GPU_CONST uint kRngPixelY = 1u;
GPU_CONST uint kRngBounceStride = 65536u;
GPU_CONST uint kRngBounceBase = 2u;           // + b * kRngBounceStride
GPU_CONST uint kRngSlotDirectionU = 0u;       // the next direction (two numbers)
GPU_CONST uint kRngSlotDirectionV = 1u;
GPU_CONST uint kRngSlotLobe = 2u;             // which lobe of a BRDF-sampling mixture
GPU_CONST uint kRngSlotRoulette = 3u;         // Russian roulette
GPU_CONST uint kRngSlotLightBase = 4u;        // + 2 * (light * lightsamples + k): a light sample's u, v

// How each backend turns these numbers into a path (each written on its own, to these rules,
// so that the same seed gives the same paths up to float rounding):
//  - Camera: a render of spp 1 samples the pixel centre (doc/scene-format.md, "Camera"); otherwise sample s
//    of pixel (x, y) is at (x + u, y + v), u, v = kRngPixelX, kRngPixelY, instead of +0.5.
//  - A frame around a unit axis n: a = |n.x| > 0.9 ? (0, 1, 0) : (1, 0, 0),
//    t = normalize(cross(a, n)), b = cross(n, t); local (x, y, z) is x t + y b + z n.
//  - With u, v = the direction slots of the vertex: hemisphere: z = u, phi = 2 pi v;
//    cosine: z = sqrt(1 - u), sin = sqrt(u), phi = 2 pi v; Phong lobe: z = u^(1 / (s + 1))
//    around r; GGX: theta_h = atan(alpha sqrt(u) / sqrt(1 - u)), phi = 2 pi v, around n, and
//    w_i = 2 (w_o . h) h - w_o; (x, y) = sin(theta) (cos phi, sin phi).
//  - BRDF sampling picks the specular lobe when the kRngSlotLobe number is below t
//    (doc/path-tracing.md, "Estimators").
//  - Light sample k of N of quad light j: (s, t) = (u, v) of its two slots; stratified:
//    ((k % m + u) / m, (k / m + v) / m), m = sqrt(N); the point a + s ab + t ac.
//  - Emissive triangles and spheres (`emission`, not quad lights) are one more light for
//    next-event estimation, after the Q quad lights: light sample k of N picks an emitter by
//    the rngEmitterPickSlot number u (the first e whose cumulative probability exceeds u;
//    each emitter's probability is proportional to area x sum(|emission|)), then a point on
//    it from (s, t) = the two numbers from rngEmitterPointSlot, stratified as a quad light's:
//    on a triangle p0 p1 p2 the point (1 - sqrt s) p0 + sqrt s (1 - t) p1 + sqrt s t p2
//    (uniform in area); on an ellipsoid (a sphere under M) the image under M of the point
//    (sqrt(1 - z^2) cos phi, sqrt(1 - z^2) sin phi, z), z = 1 - 2 s, phi = 2 pi t, of its
//    object-space sphere, whose density per world area is 1 / (4 pi r^2 |det M| |M^-T n|).
//  - Russian roulette continues when the kRngSlotRoulette number is below p.
//  - Bounce b is 0 at the camera ray's hit and grows by one at each scatter.

// The slots of emitter light sample k of N at a vertex with `quads` quad lights: the point's
// two numbers (slot, slot + 1) follow the quad lights' pairs, the picks follow those.
GPU_FN uint rngEmitterPointSlot(uint quads, uint n, uint k) { return kRngSlotLightBase + 2u * (quads * n + k); }
GPU_FN uint rngEmitterPickSlot(uint quads, uint n, uint k) { return kRngSlotLightBase + 2u * (quads + 1u) * n + k; }

// "lowbias32" (C. Wellons, 2018): an integer hash with small bias, cheap on any ISA.
GPU_FN uint rngHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

// The hash of (seed, pixel, sample): what the numbers of one sample share (a shader computes
// it once per sample).
GPU_FN uint rngSampleKey(uint seed, uint pixel, uint sampleIndex) {
  return rngHash(sampleIndex + rngHash(pixel + rngHash(seed)));
}

// The number of `dimension` in the sample whose key is `key`: rngUniform's, bit for bit.
GPU_FN float rngUniformKeyed(uint key, uint dimension) {
  return float(rngHash(dimension + key) >> 8u) * 5.9604644775390625e-8f;   // 2^-24
}

// A uniform number in [0, 1): 24 random bits, so it is exact in float and never 1.
GPU_FN float rngUniform(uint seed, uint pixel, uint sampleIndex, uint dimension) {
  return rngUniformKeyed(rngSampleKey(seed, pixel, sampleIndex), dimension);
}

// The dimension of `slot` at path vertex `bounce`.
GPU_FN uint rngDimension(uint bounce, uint slot) { return kRngBounceBase + bounce * kRngBounceStride + slot; }

struct GpuBvhNode {         // axis-aligned box, rounded outward to float
  float minX, minY, minZ;
  uint leftOrFirst;         // interior: index of the left child (right = left + 1); leaf: first primRef
  float maxX, maxY, maxZ;
  uint primCount;           // 0 for an interior node
};
GPU_ASSERT_SIZE(GpuBvhNode, 32)
GPU_ASSERT_OFFSET(GpuBvhNode, leftOrFirst, 12)
GPU_ASSERT_OFFSET(GpuBvhNode, primCount, 28)

// ---- The compute shader's interface ------------------------------------------------------------

// Descriptor bindings of raytrace.comp (set 0).
GPU_CONST uint kBindingTriangles = 0u;
GPU_CONST uint kBindingTriangleNormals = 1u;
GPU_CONST uint kBindingSpheres = 2u;
GPU_CONST uint kBindingLights = 3u;
GPU_CONST uint kBindingMaterials = 4u;
GPU_CONST uint kBindingBvhNodes = 5u;
GPU_CONST uint kBindingPrimRefs = 6u;
GPU_CONST uint kBindingPixels = 7u;       // output: one vec4 per pixel of the band, rgb = linear radiance, w = 1 when done (0: suspended)
GPU_CONST uint kBindingPathStates = 8u;   // suspended state: a GpuWhittedState per invocation (raytrace.comp) or per pixel of the band (pathtrace.comp)
GPU_CONST uint kBindingCounters = 9u;     // GpuCounters
GPU_CONST uint kBindingParams = 10u;      // GpuRenderParams (a uniform buffer)
GPU_CONST uint kBindingCount = 11u;

// Specialization constant ids. Only what changes the code is specialised: what the scene
// contains (1) or not (0), so that the driver compiles out the code of absent features, and
// the exactness cut-off. Sizes, counts and loop bounds are data (GpuRenderParams): a new
// image size or triangle count is then no new shader for the driver to compile.
GPU_CONST uint kSpecHasTriangles = 0u;
GPU_CONST uint kSpecHasSpheres = 1u;
GPU_CONST uint kSpecHasSmoothNormals = 2u;   // `trinormal`
GPU_CONST uint kSpecHasPointLights = 3u;
GPU_CONST uint kSpecHasDirectionalLights = 4u;
GPU_CONST uint kSpecHasAttenuation = 5u;     // a point light whose attenuation is not 1 0 0
GPU_CONST uint kSpecHasSpecular = 6u;        // highlights and mirror rays
GPU_CONST uint kSpecCutoff = 7u;             // the exactness cut-off of the mirror loop (below)
GPU_CONST uint kSpecCount = 8u;

// A traversal-stack entry says what its parent's read of the node told: for a leaf,
// kStackLeafBit | count << kStackCountShift | first primRef (first < 2^28, count <= 7); for an
// interior node, the index of its left child. Popping it needs no read of the node.
GPU_CONST uint kStackLeafBit = 0x80000000u;
GPU_CONST uint kStackCountShift = 28u;
GPU_CONST uint kStackFirstMask = 0x0FFFFFFFu;

GPU_CONST uint kWorkgroupSize = 8u;       // 8x8 pixels per workgroup (lavapipe: 8 wide or more)

// llvmpipe ends a shader invocation silently after 65,535 loop iterations in all. One step
// of the shader's state machine runs at most 1 + kMaxLeafPrims loop iterations, so a budget
// of this many steps per dispatch stays well inside the limit; an invocation (raytrace.comp)
// or pixel (pathtrace.comp) that needs more is suspended (its GpuWhittedState or GpuPathTracerState saved) and resumed
// by the next dispatch.
GPU_CONST uint kDefaultStepBudget = 8192u;
GPU_CONST uint kMaxLeafPrims = 4u;
// pathtrace.comp's test of every primitive (kPathSpecTestAll) is for scenes of at most this
// many primitives; it counts as one step per kMaxLeafPrims of them.
GPU_CONST uint kTestAllMaxPrims = 32u;
// raytrace.comp: each workgroup takes a run of this many 8x8 tiles of a band, each lane a
// pixel of each tile in turn, a new one when its pixel is done (VulkanOptions::pixelsPerInvocation;
// on CPU devices: a GPU gets a pixel per invocation).
GPU_CONST uint kDefaultPixelsPerInvocation = 16u;
// Entries of the shader's traversal stack and of a saved one: the BVH builder bounds the
// depth so that depth + 1 entries never exceed this (kMaxBvhDepth, host/scene/bvh.h).
GPU_CONST uint kTraversalStackSize = 96u;

// Phases of a pixel's state machine.
GPU_CONST uint kPhaseTrace = 0u;     // nearest hit of the current ray (camera or mirror)
GPU_CONST uint kPhaseLight = 1u;     // start the next light's shadow ray
GPU_CONST uint kPhaseShadow = 2u;    // any hit of the shadow ray
GPU_CONST uint kPhaseDone = 3u;
GPU_CONST uint kPhaseSampleEnd = 4u;   // pathtrace.comp: the sample is over (within a step, never saved)

// The camera in the float32 frame, as both shaders take it (camera.glsl).
struct GpuCamera {
  vec4 origin;              // xyz = look-from, w unused
  vec4 right;               // xyz = u * tan(fovx/2) / (W/2): one pixel to the right
  vec4 up;                  // xyz = v * tan(fovy/2) / (H/2): one pixel up
  vec4 back;                // xyz = w = normalize(from - at)
};
GPU_ASSERT_SIZE(GpuCamera, 64)

// raytrace.comp's exactness cut-off: a mirror ray is not traced when the most that the rest
// of the path can add or take away, |throughput| * bound * (1 + s + s^2 + ...) per channel
// (s = specular), leaves every channel's byte as it is. bound bounds the |radiance| that one
// hit can send (ambient + emission + every light at full strength); +infinity where there is
// no bound (a point light without a constant attenuation term), and the shader never cuts by
// such a channel (flatten.cpp, cutoffConstants).
struct GpuCutoff {
  vec4 bound;               // rgb = that bound per channel; w = 1 when no colour or attenuation term is negative
  vec4 specular;            // rgb = the largest |specular| of any material, per channel; w unused
};
GPU_ASSERT_SIZE(GpuCutoff, 32)

struct GpuPushConstants {
  GpuCamera camera;
  GpuCutoff cutoff;
  uint bandY0;              // first image row of this band
  uint resume;              // 0: every pixel starts fresh; 1: continue suspended pixels
  uint pad0, pad1;          // size 112 (push constants: at most 128 bytes)
};
GPU_ASSERT_SIZE(GpuPushConstants, 112)
GPU_ASSERT_OFFSET(GpuPushConstants, cutoff, 64)
GPU_ASSERT_OFFSET(GpuPushConstants, bandY0, 96)

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
  uint rootEntry;           // the root as a traversal-stack entry (above)
  // A crop computes only the pixels [originX, originX + width) x [originY, originY + height)
  // of the full image; camera rays use the full image's size and pixel coordinates
  // (doc/scene-format.md, "Camera"), so a crop's pixels are those of a full render. The whole image: origin 0 0,
  // full size = width x height.
  uint originX;
  uint originY;
  uint fullWidth;
  uint fullHeight;
  uint pad0, pad1;          // size 64 (std140 and std430 agree: only uint members)
};
GPU_ASSERT_SIZE(GpuRenderParams, 64)
GPU_ASSERT_OFFSET(GpuRenderParams, stepBudget, 16)
GPU_ASSERT_OFFSET(GpuRenderParams, rootEntry, 36)
GPU_ASSERT_OFFSET(GpuRenderParams, originX, 40)
GPU_ASSERT_OFFSET(GpuRenderParams, fullHeight, 52)

struct GpuCounters {
  uint suspended;           // invocations (raytrace.comp) or pixels (pathtrace.comp) of this dispatch that ran out of steps
  uint shadowRays;
  uint reflectionRays;
  uint nonFinite;           // pixels whose radiance was NaN or infinite (RayCounts::nonFinite)
};
GPU_ASSERT_SIZE(GpuCounters, 16)

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

// Everything a suspended invocation of raytrace.comp needs to continue where it stopped.
struct GpuWhittedState {
  vec4 throughput;          // rgb weight of the current segment, w unused
  vec4 radiance;            // rgb sum so far, w unused
  vec4 lightColor;          // rgb light colour / attenuation of the current shadow ray, w unused
  uint depth;               // mirror reflections so far
  uint tile;                // the tile of the band whose pixel the invocation computes
  uint pad0, pad1;          // size 64
  GpuTraceState trace;
};
GPU_ASSERT_SIZE(GpuWhittedState, 64 + 112 + 8 * 96)
GPU_ASSERT_OFFSET(GpuWhittedState, trace, 64)

GPU_CONST uint kNoHit = 0xFFFFFFFFu;

// ---- pathtrace.comp: the path integrators (doc/path-tracing.md) -------------------------------
// It reads the scene at the bindings of raytrace.comp (kBindingTriangles .. kBindingPrimRefs),
// and shares kBindingPathStates, kBindingCounters and kBindingParams (GpuRenderParams: sizes,
// bands, tiles, the BVH root) with it. At kBindingPixels it adds each pixel's samples into a
// vec4 (rgb = sum of the samples' radiance, w = 1 once the pixel's samples are all done).
GPU_CONST uint kBindingQuadLights = 11u;   // GpuQuadLight[] (a texel buffer with the texel reads)
GPU_CONST uint kBindingPathParams = 12u;   // GpuPathParams (a uniform buffer)
GPU_CONST uint kBindingEmitters = 13u;     // GpuEmitter[] (a storage buffer in both read modes)
GPU_CONST uint kPathBindingCount = 14u;

// Its specialization constants: ids 0-5 mean what kSpecHasTriangles .. kSpecHasAttenuation do.
GPU_CONST uint kPathSpecHasQuadLights = 6u;
GPU_CONST uint kPathSpecHasGgx = 7u;          // some material has `brdf ggx`
// The render's integrator settings (the GpuPathParams members of the same names), so that the
// driver compiles out the code of the others: lavapipe runs every branch that any lane of a
// SIMD vector takes, and a uniform's value is unknown to it. kPathSpecFromParams (the default,
// and the value when not specializing) reads the setting from GpuPathParams instead.
GPU_CONST uint kPathSpecIntegrator = 8u;
GPU_CONST uint kPathSpecNextEvent = 9u;
GPU_CONST uint kPathSpecSampling = 10u;
GPU_CONST uint kPathSpecRussianRoulette = 11u;
GPU_CONST uint kPathSpecStratified = 12u;     // 1: lightStrata > 0
GPU_CONST uint kPathSpecJitter = 13u;
GPU_CONST uint kPathSpecHasEmitters = 14u;    // some triangle or sphere emits (GpuEmitter): a feature, 0 or 1
// 1: a ray is tested against every primitive, triangles then spheres (GpuPathParams
// triangleCount and sphereCount), in a loop whose index is the same in every lane, instead of
// a walk of the BVH; for scenes of at most kTestAllMaxPrims primitives, each of them in the BVH.
GPU_CONST uint kPathSpecTestAll = 15u;
GPU_CONST uint kPathSpecCount = 16u;
GPU_CONST uint kPathSpecFromParams = 0xFFFFFFFFu;

// GpuPathParams.maxDepth of `maxdepth -1`: no limit, only Russian roulette ends a path...
GPU_CONST uint kUnlimitedDepth = 0xFFFFFFFFu;
// ...or this many bounces (maxdepth -1 without Russian roulette in a closed scene of albedo 1
// has no end): where the generator's dimensions, bounce * kRngBounceStride, would wrap.
GPU_CONST uint kMaxBounces = 0xFFFFFFFFu / kRngBounceStride - 1u;
// A shadow ray toward a point x' on a quad light ends at this fraction of |x' - x|, so that
// the light's own triangles (at t = |x' - x|, up to rounding) never block it.
GPU_CONST float kQuadShadowSpan = 0.9990234375f;   // 1 - 2^-10

// An emissive triangle or sphere that next-event estimation samples (gpu_types.h, "How each
// backend turns these numbers into a path"; the table: host/scene/emitters.h). A sample picks
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

// One render's path settings, camera and sample range (a uniform buffer; std140 and std430
// agree: vec4, 4-byte scalar and vec4-only struct members).
struct GpuPathParams {
  GpuCamera camera;
  uint integrator;          // kIntegratorAnalyticDirect, kIntegratorDirect or kIntegratorPathTracer
  uint nextEvent;           // kNextEventOff, On or Mis
  uint sampling;            // kSamplingHemisphere, Cosine or Brdf
  uint russianRoulette;     // 0 or 1
  uint maxDepth;            // D of doc/path-tracing.md, "Depth", or kUnlimitedDepth
  uint lightSamples;        // N per quad light per shading point
  uint lightStrata;         // sqrt(N) with `lightstratify on`, else 0
  uint quadLightCount;
  uint lightCount;          // point and directional lights
  uint seed;
  uint firstSample;         // this render's samples are [firstSample, firstSample + sampleCount)
  uint sampleCount;
  uint jitter;              // 0: every sample through the pixel centre (a render of spp 1); 1: uniform in the pixel
  uint emitterCount;        // entries of the GpuEmitter table (0: emissive surfaces are found by hitting only)
  float emitterWeightScale; // 1 / the emitters' total weight (GpuEmitter)
  uint triangleCount;       // the scene's triangles and spheres (read with kPathSpecTestAll)
  uint sphereCount;
  uint pad0, pad1, pad2;    // size 144
};
GPU_ASSERT_SIZE(GpuPathParams, 144)
GPU_ASSERT_OFFSET(GpuPathParams, integrator, 64)
GPU_ASSERT_OFFSET(GpuPathParams, maxDepth, 80)
GPU_ASSERT_OFFSET(GpuPathParams, seed, 100)
GPU_ASSERT_OFFSET(GpuPathParams, jitter, 112)
GPU_ASSERT_OFFSET(GpuPathParams, emitterWeightScale, 120)
GPU_ASSERT_OFFSET(GpuPathParams, sphereCount, 128)

struct GpuPathPush {
  uint bandY0;              // first image row of this band
  uint resume;              // 0: every pixel starts its samples; 1: continue suspended pixels
  uint pad0, pad1;
};
GPU_ASSERT_SIZE(GpuPathPush, 16)

// Everything a suspended pixel of pathtrace.comp needs to continue where it stopped.
struct GpuPathTracerState {
  vec4 throughput;          // rgb path throughput T, w unused
  vec4 radiance;            // rgb radiance of this sample so far, w unused
  vec4 pixelSum;            // rgb sum of the pixel's finished samples, w = pdf of the last scatter (MIS)
  vec4 pending;             // rgb what the shadow ray adds when nothing blocks it, w unused
  uint bounce;              // path vertex: 0 at the camera ray's hit
  uint sampleIndex;         // samples of this render finished
  uint pad0, pad1;          // size 80
  GpuTraceState trace;
};
GPU_ASSERT_SIZE(GpuPathTracerState, 80 + 112 + 8 * 96)
GPU_ASSERT_OFFSET(GpuPathTracerState, trace, 80)

#ifdef __cplusplus
}  // namespace gpu
#endif
#endif  // VKRT_GPU_TYPES_H
