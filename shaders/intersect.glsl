// intersect.glsl: rays against the scene, in float32, for the compute shaders (raytrace.comp,
// pathtrace.comp): boxes, triangles, spheres, the traversal stack's entries and the offsets of
// secondary rays (the traversal itself: traverse.glsl). Include after gpu_types.h and
// scene_reads.glsl, and after the specialization constants kHasTriangles, kHasSpheres and
// kHasSmoothNormals.

const float kInfinity = 3.402823466e38;

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
// The edge functions of the sheared triangle: (u, v, w), the unnormalised weights of p0, p1
// and p2 (u of edge p1-p2, v of edge p2-p0, w of edge p0-p1).
vec3 edgeWeights(GpuTriangle tri, vec3 origin, Shear sh) {
  vec3 pa = tri.p0.xyz - origin, pb = tri.p1.xyz - origin, pc = tri.p2.xyz - origin;
  precise float ax = pa[sh.kx] - sh.s.x * pa[sh.kz], ay = pa[sh.ky] - sh.s.y * pa[sh.kz];
  precise float bx = pb[sh.kx] - sh.s.x * pb[sh.kz], by = pb[sh.ky] - sh.s.y * pb[sh.kz];
  precise float cx = pc[sh.kx] - sh.s.x * pc[sh.kz], cy = pc[sh.ky] - sh.s.y * pc[sh.kz];
  precise vec3 e = vec3(cx * by - cy * bx, ax * cy - ay * cx, bx * ay - by * ax);
  return e;
}

float hitTriangle(uint index, vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, out vec2 b) {
  GpuTriangle tri = loadTriangle(index);
  vec3 e = edgeWeights(tri, origin, sh);
  float u = e.x, v = e.y, w = e.z;
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

// hitTriangle's result, bit for bit, computed without an early return (b is then undefined on
// a miss): for loops that llvmpipe runs for a whole vector, where each return costs masks.
float hitTriangleWhole(uint index, vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, out vec2 b) {
  GpuTriangle tri = loadTriangle(index);
  vec3 e = edgeWeights(tri, origin, sh);
  float u = e.x, v = e.y, w = e.z;
  bool outside = (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0);
  float det = u + v + w;
  vec3 n = vec3(tri.p0.w, tri.p1.w, tri.p2.w);
  float nDotD = dot(n, dir);
  float t = (tri.planeOffset - dot(n, origin)) / nDotD;
  b = vec2(v, w) / det;
  return !outside && det != 0.0 && nDotD != 0.0 && t > tMin && t < tMax ? t : -1.0;
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
  if (!kHasTriangles) return hitSphere(primIndex(ref), origin, dir, tMin, tMax);
  return primKind(ref) == kPrimSphere ? hitSphere(primIndex(ref), origin, dir, tMin, tMax)
                                      : hitTriangle(ref, origin, dir, sh, tMin, tMax, b);
}

uint stackEntry(GpuBvhNode n) {
  return n.primCount > 0u ? kStackLeafBit | (n.primCount << kStackCountShift) | n.leftOrFirst : n.leftOrFirst;
}

// The secondary-ray offsets at p on a primitive (the policy: gpu_limits.h);
// p and the camera are in the frame centred on the geometry. Sets hitTMin and hitGrazing.
void setSecondaryOffsets(float primitiveOffset, vec3 p, vec3 camera) {
  vec3 a = max(abs(p), abs(p - camera));
  float magnitude = max(max(a.x, a.y), a.z);
  hitTMin = max(primitiveOffset, kOffsetPerMagnitude * magnitude);
  hitGrazing = kGrazingPerMagnitude * magnitude;
}

// The tMin of a secondary ray leaving the hit with |N.dir| = cosine.
float secondaryTMin(float cosine) { return max(hitTMin, hitGrazing / max(cosine, 1e-30)); }

// At the nearest hit p = origin + t dir of primitive reference `prim` (barycentrics b of
// p1 and p2 for a triangle): the unit shading normal and the material. Also sets the
// secondary-ray offsets of p (setSecondaryOffsets).
void surfaceAt(uint prim, vec3 origin, vec3 dir, float t, vec2 b, vec3 p, vec3 camera, out vec3 normal,
               out uint material) {
  if (kHasSpheres && (!kHasTriangles || primKind(prim) == kPrimSphere)) {
    GpuSphere s = loadSphere(primIndex(prim));
    vec3 pObject = (s.objectFromWorld * vec4(origin, 1.0)).xyz + t * (s.objectFromWorld * vec4(dir, 0.0)).xyz;
    normal = normalize(transpose(mat3(s.objectFromWorld)) * (pObject - s.centerRadius.xyz));
    material = s.materialIndex;
    setSecondaryOffsets(s.rayOffset, p, camera);
  } else {
    GpuTriangle tri = loadTriangle(prim);
    if (kHasSmoothNormals && tri.normalsIndex != kNoNormals) {
      GpuTriangleNormals n = loadTriangleNormals(tri.normalsIndex);
      normal = normalize((1.0 - b.x - b.y) * n.n0.xyz + b.x * n.n1.xyz + b.y * n.n2.xyz);
    } else {
      normal = vec3(tri.p0.w, tri.p1.w, tri.p2.w);
    }
    material = tri.materialIndex;
    setSecondaryOffsets(tri.rayOffset, p, camera);
  }
}
