// shapes/triangle.glsl: the triangle, as the compute shaders see it: its read (a storage
// buffer, or texels with VKRT_TEXEL_READS), the watertight ray test, the surface at a hit,
// and a point for a light sample. Included by intersect.glsl, which dispatches over shapes.

#ifdef VKRT_TEXEL_READS
SCENE_TEXELS(kBindingTriangles) triangleWords;               // 4 texels each
SCENE_TEXELS(kBindingTriangleNormals) triangleNormalWords;   // 3 texels each
GpuTriangle loadTriangle(uint i) {
  GpuTriangle t;
  t.p0 = texelF(triangleWords, 4u * i);
  t.p1 = texelF(triangleWords, 4u * i + 1u);
  t.p2 = texelF(triangleWords, 4u * i + 2u);
  uvec4 w = texelU(triangleWords, 4u * i + 3u);
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
#else
layout(std430, binding = kBindingTriangles) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = kBindingTriangleNormals) readonly buffer TriangleNormals { GpuTriangleNormals triangleNormals[]; };
GpuTriangle loadTriangle(uint i) { return triangles[i]; }
GpuTriangleNormals loadTriangleNormals(uint i) { return triangleNormals[i]; }
#endif

vec3 triangleFaceNormal(GpuTriangle tri) { return vec3(tri.p0.w, tri.p1.w, tri.p2.w); }

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

// At a hit of triangle `index` with barycentric weights b of p1 and p2: the unit shading
// normal (interpolated for `trinormal`), the material and the secondary-ray offset.
void triangleSurface(uint index, vec2 b, out vec3 normal, out uint material, out float primitiveOffset) {
  GpuTriangle tri = loadTriangle(index);
  if (kHasSmoothNormals && tri.normalsIndex != kNoNormals) {
    GpuTriangleNormals n = loadTriangleNormals(tri.normalsIndex);
    normal = normalize((1.0 - b.x - b.y) * n.n0.xyz + b.x * n.n1.xyz + b.y * n.n2.xyz);
  } else {
    normal = triangleFaceNormal(tri);
  }
  material = tri.materialIndex;
  primitiveOffset = tri.rayOffset;
}

// sampleTriangle's density factor (1), and the face normal by which light leaving the triangle
// is measured (emission is two-sided).
float triangleDensityFactorAt(uint index, out vec3 normal) {
  normal = triangleFaceNormal(loadTriangle(index));
  return 1.0;
}

// The point (1 - sqrt s) p0 + sqrt s (1 - t) p1 + sqrt s t p2, uniform in area (density
// factor 1), with the face normal (emission is two-sided).
void sampleTriangle(uint index, float s, float t, out vec3 x, out vec3 normal, out float factor, out uint material,
                    out float primitiveOffset) {
  GpuTriangle tri = loadTriangle(index);
  float su = sqrt(s);
  x = (1.0 - su) * tri.p0.xyz + su * (1.0 - t) * tri.p1.xyz + su * t * tri.p2.xyz;
  normal = triangleFaceNormal(tri);
  factor = 1.0;
  material = tri.materialIndex;
  primitiveOffset = tri.rayOffset;
}
