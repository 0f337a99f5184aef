// intersect.glsl: rays against the scene, in float32, for the compute shaders (raytrace.comp,
// pathtrace.comp): boxes, the traversal stack's entries, the offsets of secondary rays, and
// the one dispatch over the shapes (shapes/*.glsl: each shape's read, intersection, surface
// and samples) for their tests, surfaces and samples. The traversal itself: traverse.glsl.
// Include after gpu_types.h and scene_reads.glsl, and after the specialization constants
// kHasTriangles, kHasSpheres and kHasSmoothNormals.
//
// The shapes' includes and the dispatches below are the shaders' one list of the shapes. A
// new kind tests primKind first in each dispatch: the specialised shortcuts after that
// (isSphere, and the !kHasSpheres and !kHasTriangles branches) know of triangles and spheres
// only. The test-all loop (traverse.glsl, testAll) tests those two kinds only, and the host
// leaves it off for a scene with a shape of another kind (band_layout.cpp, testsEveryPrimitive).

const float kInfinity = 3.402823466e38;
const float kPi = 3.14159265358979;

#include "shapes/triangle.glsl"
#include "shapes/sphere.glsl"

// Of the shaded hit: the least tMin of a secondary ray leaving it, and the grazing term.
float hitTMin, hitGrazing;

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

// Whether primitive reference `prim` is a sphere (else a triangle), known at compile time
// when the scene holds one kind only.
bool isSphere(uint prim) { return kHasSpheres && (!kHasTriangles || primKind(prim) == kPrimSphere); }

// A BVH leaf's primitive reference: a sphere or a triangle.
float hitPrimitive(uint ref, vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, out vec2 b) {
  b = vec2(0.0);
  if (!kHasSpheres) return hitTriangle(ref, origin, dir, sh, tMin, tMax, b);
  if (!kHasTriangles) return hitSphere(primIndex(ref), origin, dir, tMin, tMax);
  return primKind(ref) == kPrimSphere ? hitSphere(primIndex(ref), origin, dir, tMin, tMax)
                                      : hitTriangle(ref, origin, dir, sh, tMin, tMax, b);
}

uint stackEntry(GpuBvhNode n) {
  return n.primCount > 0u ? kStackLeafBit | (n.primCount << kStackCountShift) | n.leftOrFirst : n.leftOrFirst;
}

// The secondary-ray offsets (the policy: gpu_limits.h). p and the camera are in the frame
// centred on the geometry; m = max(|p|_max, |p - camera|_max).
float offsetMagnitude(vec3 p, vec3 camera) {
  vec3 a = max(abs(p), abs(p - camera));
  return max(max(a.x, a.y), a.z);
}

// At p on a primitive whose offset is primitiveOffset: sets hitTMin and hitGrazing, the terms
// of secondaryTMin.
void setSecondaryOffsets(float primitiveOffset, vec3 p, vec3 camera) {
  float magnitude = offsetMagnitude(p, camera);
  hitTMin = max(primitiveOffset, kOffsetPerMagnitude * magnitude);
  hitGrazing = kGrazingPerMagnitude * magnitude;
}

// The tMin of a secondary ray leaving the hit with |N.dir| = cosine.
float secondaryTMin(float cosine) { return max(hitTMin, hitGrazing / max(cosine, 1e-30)); }

// The same least t for a ray leaving another point p (a light sample's), whose primitive's
// offset is primitiveOffset, at |N.dir| = cosine.
float secondaryTMinAt(float primitiveOffset, vec3 p, vec3 camera, float cosine) {
  float magnitude = offsetMagnitude(p, camera);
  return max(max(primitiveOffset, kOffsetPerMagnitude * magnitude), kGrazingPerMagnitude * magnitude / max(cosine, 1e-30));
}

// At the nearest hit p = origin + t dir of primitive reference `prim` (barycentrics b of
// p1 and p2 for a triangle): the unit shading normal and the material. Also sets the
// secondary-ray offsets of p (setSecondaryOffsets).
void surfaceAt(uint prim, vec3 origin, vec3 dir, float t, vec2 b, vec3 p, vec3 camera, out vec3 normal,
               out uint material) {
  float primitiveOffset;
  if (isSphere(prim))
    sphereSurface(primIndex(prim), origin, dir, t, normal, material, primitiveOffset);
  else
    triangleSurface(prim, b, normal, material, primitiveOffset);
  setSecondaryOffsets(primitiveOffset, p, camera);
}

// A point of primitive `prim` for a light sample, from the two numbers (s, t) in [0, 1)^2 (the
// rules of doc/design.md, "Random numbers and sampling rules"): the point, the unit normal
// there, the factor of its density per world area over the primitive's (1 for a triangle),
// the material and the primitive's secondary-ray offset.
void samplePoint(uint prim, float s, float t, out vec3 x, out vec3 normal, out float factor, out uint material,
                 out float primitiveOffset) {
  if (isSphere(prim))
    sampleSphere(primIndex(prim), s, t, x, normal, factor, material, primitiveOffset);
  else
    sampleTriangle(prim, s, t, x, normal, factor, material, primitiveOffset);
}

// At point p of primitive `prim`: the unit normal by which light leaving it is measured, and
// the factor of samplePoint's density there.
float densityFactorAt(uint prim, vec3 p, out vec3 normal) {
  return isSphere(prim) ? sphereDensityFactorAt(primIndex(prim), p, normal) : triangleDensityFactorAt(prim, normal);
}
