// raytrace.comp: one invocation per pixel of a band. Camera ray, nearest hit through the BVH,
// shading with shadow rays, and an iterative mirror loop carrying a throughput weight, bounded
// by maxdepth. Written as a state machine of bounded steps so that no invocation exceeds
// llvmpipe's loop budget: a pixel that runs out of steps saves its state and the host
// dispatches again (see kDefaultStepBudget in gpu_types.h).
// Its math is float32 and written independently of the CPU reference (host/cpu/).
#version 450
#extension GL_GOOGLE_include_directive : require

#include "gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;   // kWorkgroupSize

// Specialization constants: only what changes the code (gpu_types.h, kSpec*).
layout(constant_id = 0) const bool kHasTriangles = true;
layout(constant_id = 1) const bool kHasSpheres = true;
layout(constant_id = 2) const bool kHasSmoothNormals = true;
layout(constant_id = 3) const bool kHasPointLights = true;
layout(constant_id = 4) const bool kHasDirectionalLights = true;
layout(constant_id = 5) const bool kHasAttenuation = true;
layout(constant_id = 6) const bool kHasSpecular = true;
layout(constant_id = 7) const bool kCutoff = true;

// Scene reads: storage buffers, or (VKRT_TEXEL_READS) the same bytes through uint texel-buffer
// views, which lavapipe reads 2.7-3x faster inside loops (bench/ measures both). Only uint
// views: a float view may flush denormal-looking indices or canonicalise NaN-looking words.
#ifdef VKRT_TEXEL_READS
layout(binding = kBindingTriangles) uniform usamplerBuffer triangleWords;        // RGBA32UI, 4 texels each
layout(binding = kBindingTriangleNormals) uniform usamplerBuffer triangleNormalWords;  // RGBA32UI, 3 texels each
layout(binding = kBindingSpheres) uniform usamplerBuffer sphereWords;          // RGBA32UI, 6 texels each
layout(binding = kBindingLights) uniform usamplerBuffer lightWords;           // RGBA32UI, 3 texels each
layout(binding = kBindingMaterials) uniform usamplerBuffer materialWords;        // RGBA32UI, 4 texels each
layout(binding = kBindingBvhNodes) uniform usamplerBuffer nodeWords;            // RGBA32UI, 2 texels each
layout(binding = kBindingPrimRefs) uniform usamplerBuffer primRefWords;         // R32UI

vec4 texelF(usamplerBuffer b, uint i) { return uintBitsToFloat(texelFetch(b, int(i))); }

GpuTriangle loadTriangle(uint i) {
  GpuTriangle t;
  t.p0 = texelF(triangleWords, 4u * i);
  t.p1 = texelF(triangleWords, 4u * i + 1u);
  t.p2 = texelF(triangleWords, 4u * i + 2u);
  uvec4 w = texelFetch(triangleWords, int(4u * i + 3u));
  t.materialIndex = w.x;
  t.normalsIndex = w.y;
  t.rayOffset = uintBitsToFloat(w.z);
  t.planeOffset = uintBitsToFloat(w.w);
  return t;
}
GpuTriangleNormals loadTriangleNormals(uint i) {
  GpuTriangleNormals n;
  n.n0 = texelF(triangleNormalWords, 3u * i);
  n.n1 = texelF(triangleNormalWords, 3u * i + 1u);
  n.n2 = texelF(triangleNormalWords, 3u * i + 2u);
  return n;
}
GpuSphere loadSphere(uint i) {
  GpuSphere s;
  s.objectFromWorld = mat4(texelF(sphereWords, 6u * i), texelF(sphereWords, 6u * i + 1u),
                           texelF(sphereWords, 6u * i + 2u), texelF(sphereWords, 6u * i + 3u));
  s.centerRadius = texelF(sphereWords, 6u * i + 4u);
  uvec4 w = texelFetch(sphereWords, int(6u * i + 5u));
  s.materialIndex = w.x;
  s.rayOffset = uintBitsToFloat(w.y);
  return s;
}
GpuLight loadLight(uint i) {
  GpuLight l;
  l.positionOrDirection = texelF(lightWords, 3u * i);
  l.color = texelF(lightWords, 3u * i + 1u);
  l.attenuation = texelF(lightWords, 3u * i + 2u);
  return l;
}
GpuMaterial loadMaterial(uint i) {
  GpuMaterial m;
  m.ambient = texelF(materialWords, 4u * i);
  m.diffuse = texelF(materialWords, 4u * i + 1u);
  m.specular = texelF(materialWords, 4u * i + 2u);
  m.emission = texelF(materialWords, 4u * i + 3u);
  return m;
}
GpuBvhNode loadNode(uint i) {
  uvec4 a = texelFetch(nodeWords, int(2u * i)), b = texelFetch(nodeWords, int(2u * i + 1u));
  GpuBvhNode n;
  n.minX = uintBitsToFloat(a.x); n.minY = uintBitsToFloat(a.y); n.minZ = uintBitsToFloat(a.z);
  n.leftOrFirst = a.w;
  n.maxX = uintBitsToFloat(b.x); n.maxY = uintBitsToFloat(b.y); n.maxZ = uintBitsToFloat(b.z);
  n.primCount = b.w;
  return n;
}
uint loadPrimRef(uint i) { return texelFetch(primRefWords, int(i)).x; }
#else
layout(std430, binding = kBindingTriangles) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = kBindingTriangleNormals) readonly buffer TriangleNormals { GpuTriangleNormals triangleNormals[]; };
layout(std430, binding = kBindingSpheres) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = kBindingLights) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = kBindingMaterials) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = kBindingBvhNodes) readonly buffer BvhNodes { GpuBvhNode nodes[]; };
layout(std430, binding = kBindingPrimRefs) readonly buffer PrimRefs { uint primRefs[]; };

GpuTriangle loadTriangle(uint i) { return triangles[i]; }
GpuTriangleNormals loadTriangleNormals(uint i) { return triangleNormals[i]; }
GpuSphere loadSphere(uint i) { return spheres[i]; }
GpuLight loadLight(uint i) { return lights[i]; }
GpuMaterial loadMaterial(uint i) { return materials[i]; }
GpuBvhNode loadNode(uint i) { return nodes[i]; }
uint loadPrimRef(uint i) { return primRefs[i]; }
#endif
layout(std430, binding = kBindingPixels) buffer Pixels { vec4 pixels[]; };   // rgb radiance; w 0: suspended
layout(std430, binding = kBindingPathStates) buffer PathStates { GpuPathState states[]; };
layout(std430, binding = kBindingCounters) buffer Counters { GpuCounters counters; };

layout(std140, binding = kBindingParams) uniform Params { GpuRenderParams params; };
layout(push_constant) uniform Push { GpuPushConstants pc; };

const float kInfinity = 3.402823466e38;

// ---- per-pixel state (registers; saved to states[] only on suspension) ----------------------
vec3 rayOrigin, rayDir;
float rayTMin, bestT, bestB1, bestB2;
vec3 throughput, radiance, hitPoint, hitNormal, shadowDir, lightColor;
float shadowTMax, nDotL, hitTMin, hitGrazing;
uint phase, depth, lightIndex, sp, hitPrim, hitMaterial;
// A local array is per-lane scratch memory in llvmpipe; its size must be a constant.
uint stack[kTraversalStackSize];     // entries (kStackLeafBit) of nodes whose boxes the ray enters
float stackT[kTraversalStackSize];   // the entry distance of each, to skip it once a nearer hit is known
uint shadowRays = 0u, reflectionRays = 0u;

// ---- intersection (float32) ------------------------------------------------------------------

// A reciprocal that is never infinite: a zero component becomes a huge finite value, so the
// slab products are never 0 * inf.
vec3 safeInverse(vec3 d) {
  const float tiny = 1e-30;
  return 1.0 / vec3(abs(d.x) > tiny ? d.x : (d.x < 0.0 ? -tiny : tiny),
                    abs(d.y) > tiny ? d.y : (d.y < 0.0 ? -tiny : tiny),
                    abs(d.z) > tiny ? d.z : (d.z < 0.0 ? -tiny : tiny));
}

// Entry distance of the ray into a node's box within (tMin, tMax), or kInfinity when missed.
float boxEntry(GpuBvhNode n, vec3 origin, vec3 invDir, float tMin, float tMax) {
  vec3 t0 = (vec3(n.minX, n.minY, n.minZ) - origin) * invDir;
  vec3 t1 = (vec3(n.maxX, n.maxY, n.maxZ) - origin) * invDir;
  vec3 tNear = min(t0, t1), tFar = max(t0, t1);
  float enter = max(max(tNear.x, tNear.y), max(tNear.z, tMin));
  float leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax));
  return enter <= leave ? enter : kInfinity;
}

// The watertight ray/triangle test of Woop, Benthin and Wald (2013): the ray is sheared onto
// +z (its largest axis), and the edge functions are computed from the sheared vertices alone,
// so two triangles that share an edge compute the same value for it with opposite signs and
// a ray can never slip between them. `precise` forbids fused multiply-adds there, which
// would break that symmetry. Per-ray constants:
struct Shear {
  uint kx, ky, kz;   // the permuted axes: kz is the direction's largest
  vec3 s;            // dir[kx] / dir[kz], dir[ky] / dir[kz], 1 / dir[kz]
};

Shear shearFor(vec3 dir) {
  vec3 a = abs(dir);
  Shear sh;
  sh.kz = a.x >= a.y ? (a.x >= a.z ? 0u : 2u) : (a.y >= a.z ? 1u : 2u);
  sh.kx = sh.kz == 2u ? 0u : sh.kz + 1u;
  sh.ky = sh.kx == 2u ? 0u : sh.kx + 1u;
  if (dir[sh.kz] < 0.0) {   // keep the winding: swap x and y
    uint k = sh.kx;
    sh.kx = sh.ky;
    sh.ky = k;
  }
  sh.s = vec3(dir[sh.kx] / dir[sh.kz], dir[sh.ky] / dir[sh.kz], 1.0 / dir[sh.kz]);
  return sh;
}

// Returns t in (tMin, tMax) or -1; b = the barycentric weights of p1 and p2. A triangle seen
// edge-on or of zero area (the host leaves those out anyway) is missed, never NaN.
float hitTriangle(uint index, vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, out vec2 b) {
  GpuTriangle tri = loadTriangle(index);
  vec3 pa = tri.p0.xyz - origin, pb = tri.p1.xyz - origin, pc = tri.p2.xyz - origin;
  precise float ax = pa[sh.kx] - sh.s.x * pa[sh.kz], ay = pa[sh.ky] - sh.s.y * pa[sh.kz];
  precise float bx = pb[sh.kx] - sh.s.x * pb[sh.kz], by = pb[sh.ky] - sh.s.y * pb[sh.kz];
  precise float cx = pc[sh.kx] - sh.s.x * pc[sh.kz], cy = pc[sh.ky] - sh.s.y * pc[sh.kz];
  precise float u = cx * by - cy * bx;   // edge p1-p2: the weight of p0
  precise float v = ax * cy - ay * cx;   // edge p2-p0: the weight of p1
  precise float w = bx * ay - by * ax;   // edge p0-p1: the weight of p2
  b = vec2(0.0);
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return -1.0;
  float det = u + v + w;
  vec3 n = vec3(tri.p0.w, tri.p1.w, tri.p2.w);
  float nDotD = dot(n, dir);
  if (det == 0.0 || nDotD == 0.0) return -1.0;
  // t from the plane stored in double precision: its error follows the ray origin's
  // magnitude, not the size of the triangle (the corners of a vast one round coarsely).
  float t = (tri.planeOffset - dot(n, origin)) / nDotD;
  b = vec2(v, w) / det;
  return (t > tMin && t < tMax) ? t : -1.0;
}

// The ray goes into object space unnormalised, so t is the world t. The discriminant is
// formed as a * (r^2 - |l|^2) with l the offset of the closest point, not as b^2 - ac, which
// loses the hit to cancellation when the ray starts far away.
float hitSphere(uint index, vec3 origin, vec3 dir, float tMin, float tMax) {
  GpuSphere s = loadSphere(index);
  vec3 o = (s.objectFromWorld * vec4(origin, 1.0)).xyz - s.centerRadius.xyz;
  vec3 d = (s.objectFromWorld * vec4(dir, 0.0)).xyz;
  float a = dot(d, d);
  float b = dot(o, d);
  float r = s.centerRadius.w;
  vec3 l = o - (b / a) * d;
  float disc = a * (r * r - dot(l, l));
  if (disc < 0.0 || a == 0.0) return -1.0;
  float q = -b - (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc);
  float c = dot(o, o) - r * r;
  float t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  float tNear = min(t0, t1), tFar = max(t0, t1);
  float t = tNear > tMin ? tNear : tFar;
  return (t > tMin && t < tMax) ? t : -1.0;
}

// A BVH leaf's primitive reference: a sphere or a triangle.
float hitPrimitive(uint ref, vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, out vec2 b) {
  b = vec2(0.0);
  if (!kHasSpheres) return hitTriangle(ref, origin, dir, sh, tMin, tMax, b);
  if (!kHasTriangles) return hitSphere(ref & ~kPrimSphereBit, origin, dir, tMin, tMax);
  return (ref & kPrimSphereBit) != 0u ? hitSphere(ref & ~kPrimSphereBit, origin, dir, tMin, tMax)
                                      : hitTriangle(ref, origin, dir, sh, tMin, tMax, b);
}

// ---- the state machine's steps -----------------------------------------------------------------

void startRay(vec3 origin, vec3 dir, float tMin) {
  rayOrigin = origin;
  rayDir = dir;
  rayTMin = tMin;
  bestT = kInfinity;
  hitPrim = kNoHit;
  sp = params.primCount > 0u ? 1u : 0u;   // an empty scene's root is an empty leaf: nothing to visit
  stack[0] = params.rootEntry;
  stackT[0] = 0.0;
  phase = kPhaseTrace;
}

uint stackEntry(GpuBvhNode n) {
  return n.primCount > 0u ? kStackLeafBit | (n.primCount << kStackCountShift) | n.leftOrFirst : n.leftOrFirst;
}

// Tests the two children of an interior node, which are adjacent in the array (one 4-texel
// read), and pushes those the ray enters within (tMin, tMax), the nearer one last.
void pushChildren(uint left, vec3 origin, vec3 invDir, float tMin, float tMax) {
  GpuBvhNode l = loadNode(left), r = loadNode(left + 1u);
  float tl = boxEntry(l, origin, invDir, tMin, tMax);
  float tr = boxEntry(r, origin, invDir, tMin, tMax);
  bool leftFirst = tl <= tr;
  float tNear = leftFirst ? tl : tr, tFar = leftFirst ? tr : tl;
  if (tFar != kInfinity) {
    stack[sp] = stackEntry(leftFirst ? r : l);
    stackT[sp++] = tFar;
  }
  if (tNear != kInfinity) {
    stack[sp] = stackEntry(leftFirst ? l : r);
    stackT[sp++] = tNear;
  }
}

// The secondary-ray offsets at p on a primitive (the policy: gpu_types.h, "Secondary rays");
// p is in the frame centred on the geometry. Sets hitTMin and hitGrazing.
void setSecondaryOffsets(float primitiveOffset, vec3 p) {
  vec3 a = max(abs(p), abs(p - pc.cameraOrigin.xyz));
  float magnitude = max(max(a.x, a.y), a.z);
  hitTMin = max(primitiveOffset, kOffsetPerMagnitude * magnitude);
  hitGrazing = kGrazingPerMagnitude * magnitude;
}

// The tMin of a secondary ray leaving the hit with |N.dir| = cosine.
float secondaryTMin(float cosine) { return max(hitTMin, hitGrazing / max(cosine, 1e-30)); }

// The nearest hit is known: ambient and emission, then the lights one by one.
void beginShading() {
  hitPoint = rayOrigin + bestT * rayDir;
  if (kHasSpheres && (!kHasTriangles || (hitPrim & kPrimSphereBit) != 0u)) {
    GpuSphere s = loadSphere(hitPrim & ~kPrimSphereBit);
    vec3 pObject = (s.objectFromWorld * vec4(rayOrigin, 1.0)).xyz + bestT * (s.objectFromWorld * vec4(rayDir, 0.0)).xyz;
    hitNormal = normalize(transpose(mat3(s.objectFromWorld)) * (pObject - s.centerRadius.xyz));
    hitMaterial = s.materialIndex;
    setSecondaryOffsets(s.rayOffset, hitPoint);
  } else {
    GpuTriangle tri = loadTriangle(hitPrim);
    if (kHasSmoothNormals && tri.normalsIndex != kNoNormals) {
      GpuTriangleNormals n = loadTriangleNormals(tri.normalsIndex);
      hitNormal = normalize((1.0 - bestB1 - bestB2) * n.n0.xyz + bestB1 * n.n1.xyz + bestB2 * n.n2.xyz);
    } else {
      hitNormal = vec3(tri.p0.w, tri.p1.w, tri.p2.w);
    }
    hitMaterial = tri.materialIndex;
    setSecondaryOffsets(tri.rayOffset, hitPoint);
  }
  GpuMaterial m = loadMaterial(hitMaterial);
  radiance += throughput * (m.ambient.rgb + m.emission.rgb);
  lightIndex = 0u;
  phase = kPhaseLight;
}

// The exactness cut-off (GpuPushConstants): true when the rest of a path whose next segment
// has weight `weight` and is segment `nextDepth` cannot change any byte of the pixel, as the
// output encodes it (host/image/encode.h: floor(clamp(c, 0, 1) * 255) in float, gamma 1).
bool restCannotChangePixel(vec3 weight, uint nextDepth) {
  bool nonNegative = pc.cutoffBound.w != 0.0;
  if (nonNegative && all(greaterThanEqual(radiance, vec3(1.0)))) return true;   // saturated
  // 1 + s + ... + s^(n-1) for the n segments left: at most n, and at most 1 / (1 - s) when
  // s < 1 (cheaper than the exact sum, and still an upper bound).
  float n = float(params.maxDepth - nextDepth + 1u);
  vec3 s = pc.cutoffSpecular.rgb;
  vec3 series = mix(vec3(n), min(vec3(n), 1.0 / max(1.0 - s, vec3(1e-30))), lessThan(s, vec3(1.0)));
  // A margin for float rounding in the sums the bound stands for.
  vec3 reach = abs(weight) * pc.cutoffBound.rgb * series * 1.001 + 1e-6;
  if (!all(lessThan(reach, vec3(kInfinity)))) return false;
  vec3 low = nonNegative ? radiance : radiance - reach, high = radiance + reach;
  vec3 lowBytes = floor(clamp(low, 0.0, 1.0) * 255.0), highBytes = floor(clamp(high, 0.0, 1.0) * 255.0);
  return all(equal(lowBytes, highBytes));
}

// After the last light: the mirror ray, or the end of the path.
void reflectOrFinish() {
  vec3 specular = loadMaterial(hitMaterial).specular.rgb;
  if (kHasSpecular && depth < params.maxDepth && any(notEqual(specular, vec3(0.0))) &&
      !(kCutoff && restCannotChangePixel(throughput * specular, depth + 1u))) {
    ++depth;
    ++reflectionRays;
    throughput *= specular;
    vec3 mirror = normalize(rayDir - 2.0 * dot(rayDir, hitNormal) * hitNormal);
    startRay(hitPoint, mirror, secondaryTMin(abs(dot(mirror, hitNormal))));
  } else {
    phase = kPhaseDone;
  }
}

// Prepares light `lightIndex`: its shadow ray, or skips a light that cannot contribute.
void lightStep() {
  if (lightIndex >= params.lightCount) {
    reflectOrFinish();
    return;
  }
  GpuLight light = loadLight(lightIndex);
  vec3 toLight;
  float divisor = 1.0;
  shadowTMax = kInfinity;
  if (kHasPointLights && (!kHasDirectionalLights || light.positionOrDirection.w == kPointLight)) {
    vec3 v = light.positionOrDirection.xyz - hitPoint;
    float distance = length(v);
    toLight = v / distance;
    shadowTMax = distance;
    if (kHasAttenuation)
      divisor = light.attenuation.x + light.attenuation.y * distance + light.attenuation.z * distance * distance;
  } else {
    toLight = light.positionOrDirection.xyz;
  }
  nDotL = dot(hitNormal, toLight);
  if (!(nDotL > 0.0)) {   // a light behind the surface adds nothing (SPEC section 7)
    ++lightIndex;
    return;
  }
  ++shadowRays;
  shadowDir = toLight;
  // Finite even for a tiny divisor, so that a zero material term times it stays 0, not NaN.
  lightColor = clamp(light.color.rgb / divisor, -kInfinity, kInfinity);
  sp = params.primCount > 0u ? 1u : 0u;
  stack[0] = params.rootEntry;
  stackT[0] = 0.0;
  phase = kPhaseShadow;
}

void addLightContribution() {
  GpuMaterial m = loadMaterial(hitMaterial);
  vec3 lit = m.diffuse.rgb * nDotL;
  if (kHasSpecular) {
    vec3 halfVector = normalize(shadowDir - rayDir);
    // At most 1, as it is exactly: float rounding may give 1 + 1e-7, and a high shininess would
    // raise that above the exactness cut-off's bound.
    float nDotH = clamp(dot(hitNormal, halfVector), 0.0, 1.0);
    float shininess = m.specular.w;
    // pow(0, s) is undefined in GLSL: define it as C does (1 for s = 0, else 0).
    float highlight = nDotH > 0.0 ? pow(nDotH, shininess) : (shininess == 0.0 ? 1.0 : 0.0);
    lit += m.specular.rgb * highlight;
  }
  radiance += throughput * lightColor * lit;
}

// True when the entry on top of the traversal stack is an interior node.
bool nextIsInterior() { return sp > 0u && (stack[sp - 1u] & kStackLeafBit) == 0u; }

// One leaf of a traversal, after the interior nodes above it: the nearest-hit traversal of
// the current ray (kPhaseTrace) or the any-hit one of a shadow ray (kPhaseShadow). One
// function for both, so that lanes of a SIMD vector in different phases run the expensive
// part once. Interior nodes are walked in an inner loop until this lane's next entry is a
// leaf, so that the lanes of a vector test their leaves together instead of taking turns
// with lanes still descending (the "while-while" order of Aila and Laine). Each node is a
// step of the budget.
void traversalStep(inout uint step) {
  bool shadow = phase == kPhaseShadow;
  vec3 origin = shadow ? hitPoint : rayOrigin;
  vec3 dir = shadow ? shadowDir : rayDir;
  float tMin = shadow ? secondaryTMin(nDotL) : rayTMin;
  float tMax = shadow ? shadowTMax : bestT;
  if (nextIsInterior()) {
    vec3 invDir = safeInverse(dir);
    while (nextIsInterior() && step < params.stepBudget) {
      --sp;
      ++step;
      if (stackT[sp] < tMax) pushChildren(stack[sp], origin, invDir, tMin, tMax);
    }
    if (nextIsInterior()) return;   // out of steps
  }
  if (sp == 0u) {   // traversal over
    if (shadow) {   // nothing in the way
      addLightContribution();
      ++lightIndex;
      phase = kPhaseLight;
    } else if (hitPrim != kNoHit) {
      beginShading();
    } else {
      phase = kPhaseDone;   // a miss is black
    }
    return;
  }
  --sp;
  if (stackT[sp] >= tMax) return;   // entered beyond the nearest hit so far
  uint entry = stack[sp];
  uint first = entry & kStackFirstMask, count = (entry >> kStackCountShift) & 7u;
  Shear sh;
  if (kHasTriangles) sh = shearFor(dir);
  for (uint i = 0u; i < count; ++i) {
    uint ref = loadPrimRef(first + i);
    vec2 b;
    float t = hitPrimitive(ref, origin, dir, sh, tMin, tMax, b);
    if (t > 0.0) {
      if (shadow) {   // blocked
        sp = 0u;
        ++lightIndex;
        phase = kPhaseLight;
        return;
      }
      tMax = t;
      bestT = t;
      hitPrim = ref;
      bestB1 = b.x;
      bestB2 = b.y;
    }
  }
}

// ---- suspension ----------------------------------------------------------------------------------

void saveState(uint slot) {
  states[slot].origin = vec4(rayOrigin, rayTMin);
  states[slot].direction = vec4(rayDir, bestT);
  states[slot].throughput = vec4(throughput, bestB1);
  states[slot].radiance = vec4(radiance, bestB2);
  states[slot].hitPoint = vec4(hitPoint, hitTMin);
  states[slot].hitNormal = vec4(hitNormal, hitGrazing);
  states[slot].shadowDir = vec4(shadowDir, shadowTMax);
  states[slot].lightColor = vec4(lightColor, nDotL);
  states[slot].phase = phase;
  states[slot].depth = depth;
  states[slot].lightIndex = lightIndex;
  states[slot].stackSize = sp;
  states[slot].hitPrim = hitPrim;
  states[slot].hitMaterial = hitMaterial;
  for (uint i = 0u; i < sp; ++i) states[slot].stack[i] = stack[i];
}

void loadState(uint slot) {
  rayOrigin = states[slot].origin.xyz;
  rayTMin = states[slot].origin.w;
  rayDir = states[slot].direction.xyz;
  bestT = states[slot].direction.w;
  throughput = states[slot].throughput.rgb;
  bestB1 = states[slot].throughput.w;
  radiance = states[slot].radiance.rgb;
  bestB2 = states[slot].radiance.w;
  hitPoint = states[slot].hitPoint.xyz;
  hitTMin = states[slot].hitPoint.w;
  hitNormal = states[slot].hitNormal.xyz;
  hitGrazing = states[slot].hitNormal.w;
  shadowDir = states[slot].shadowDir.xyz;
  shadowTMax = states[slot].shadowDir.w;
  lightColor = states[slot].lightColor.rgb;
  nDotL = states[slot].lightColor.w;
  phase = states[slot].phase;
  depth = states[slot].depth;
  lightIndex = states[slot].lightIndex;
  sp = states[slot].stackSize;
  hitPrim = states[slot].hitPrim;
  hitMaterial = states[slot].hitMaterial;
  for (uint i = 0u; i < sp; ++i) {
    stack[i] = states[slot].stack[i];
    stackT[i] = 0.0;   // entry distances are not saved: a resumed pixel only culls less
  }
}

void main() {
  // Workgroups visit the band's tiles in a scattered order, so that each of lavapipe's threads
  // (which take contiguous runs of workgroups) gets a share of every part of the image.
  uint tilesInBand = params.tilesX * ((params.bandHeight + kWorkgroupSize - 1u) / kWorkgroupSize);
  uint tile = (gl_WorkGroupID.x * params.tileOrderStride) % tilesInBand;
  uint x = (tile % params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.x;
  uint yInBand = (tile / params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.y;
  uint y = pc.bandY0 + yInBand;
  if (x >= params.width || yInBand >= params.bandHeight || y >= params.height) return;
  uint slot = yInBand * params.width + x;

  if (pc.resume != 0u) {
    if (pixels[slot].w != 0.0) return;   // finished in an earlier round
    loadState(slot);
  } else {
    // Camera ray through the pixel centre (SPEC section 3), in the full image's pixel
    // coordinates: a crop's pixels are those of the whole image.
    float a = (float(x + params.originX) + 0.5) - 0.5 * float(params.fullWidth);
    float b = 0.5 * float(params.fullHeight) - (float(y + params.originY) + 0.5);
    vec3 dir = normalize(a * pc.cameraRight.xyz + b * pc.cameraUp.xyz - pc.cameraBack.xyz);
    throughput = vec3(1.0);
    radiance = vec3(0.0);
    depth = 0u;
    startRay(pc.cameraOrigin.xyz, dir, 0.0);
  }

  for (uint step = 0u; step < params.stepBudget && phase != kPhaseDone; ++step) {
    if (phase == kPhaseLight)
      lightStep();
    else
      traversalStep(step);
  }

  if (shadowRays + reflectionRays > 0u) {
    atomicAdd(counters.shadowRays, shadowRays);
    atomicAdd(counters.reflectionRays, reflectionRays);
  }
  if (phase != kPhaseDone) {
    saveState(slot);
    pixels[slot] = vec4(0.0);
    atomicAdd(counters.suspended, 1u);
    return;
  }
  // The guard: a NaN or infinite pixel is counted, so that none reaches the image unseen
  // (the output encodes NaN as 0 and an infinity as 0 or 1).
  if (any(isnan(radiance)) || any(isinf(radiance))) atomicAdd(counters.nonFinite, 1u);
  pixels[slot] = vec4(radiance, 1.0);
}
