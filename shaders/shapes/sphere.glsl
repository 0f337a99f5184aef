// shapes/sphere.glsl: the sphere under a transform (an ellipsoid), as the compute shaders
// see it: its read (a storage buffer, or texels with VKRT_TEXEL_READS), the ray test, the
// surface at a hit, and a point for a light sample with its density. Included by
// intersect.glsl, which dispatches over shapes.

#ifdef VKRT_TEXEL_READS
SCENE_TEXELS(kBindingSpheres) sphereWords;   // 6 texels each
GpuSphere loadSphere(uint i) {
  GpuSphere s;
  s.objectFromWorld = mat4(texelF(sphereWords, 6u * i), texelF(sphereWords, 6u * i + 1u),
                           texelF(sphereWords, 6u * i + 2u), texelF(sphereWords, 6u * i + 3u));
  s.centerRadius = texelF(sphereWords, 6u * i + 4u);
  uvec4 w = texelU(sphereWords, 6u * i + 5u);
  s.materialIndex = w.x;
  s.rayOffset = uintBitsToFloat(w.y);
  return s;
}
#else
layout(std430, binding = kBindingSpheres) readonly buffer Spheres { GpuSphere spheres[]; };
GpuSphere loadSphere(uint i) { return spheres[i]; }
#endif

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

// At the hit origin + t dir of sphere `index`: the unit normal, the material and the
// secondary-ray offset.
void sphereSurface(uint index, vec3 origin, vec3 dir, float t, out vec3 normal, out uint material,
                   out float primitiveOffset) {
  GpuSphere s = loadSphere(index);
  vec3 pObject = (s.objectFromWorld * vec4(origin, 1.0)).xyz + t * (s.objectFromWorld * vec4(dir, 0.0)).xyz;
  normal = normalize(transpose(mat3(s.objectFromWorld)) * (pObject - s.centerRadius.xyz));
  material = s.materialIndex;
  primitiveOffset = s.rayOffset;
}

// At the point of ellipsoid s whose object-space unit normal is nObject: the unit world
// normal, and 1 / (|det M|^(1/3) |M^-T n|), M = the inverse of objectFromWorld: the factor
// of a light sample's density per world area there (GpuEmitter).
float sphereDensityFactor(GpuSphere s, vec3 nObject, out vec3 normal) {
  mat3 o = mat3(s.objectFromWorld);
  vec3 m = transpose(o) * nObject;   // M^-T n
  float len = length(m);
  normal = m / len;
  return pow(abs(determinant(o)), 1.0 / 3.0) / len;
}

// sphereDensityFactor at world point p of sphere `index`.
float sphereDensityFactorAt(uint index, vec3 p, out vec3 normal) {
  GpuSphere s = loadSphere(index);
  vec3 pObject = (s.objectFromWorld * vec4(p, 1.0)).xyz - s.centerRadius.xyz;
  return sphereDensityFactor(s, normalize(pObject), normal);
}

// The image under M of the point (sqrt(1 - z^2) cos phi, sqrt(1 - z^2) sin phi, z),
// z = 1 - 2 s, phi = 2 pi t, of the object-space sphere.
void sampleSphere(uint index, float s, float t, out vec3 x, out vec3 normal, out float factor, out uint material,
                  out float primitiveOffset) {
  GpuSphere sphere = loadSphere(index);
  float z = 1.0 - 2.0 * s, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * t;
  vec3 nObject = vec3(r * cos(phi), r * sin(phi), z);
  vec3 pObject = sphere.centerRadius.xyz + sphere.centerRadius.w * nObject;
  x = inverse(mat3(sphere.objectFromWorld)) * (pObject - sphere.objectFromWorld[3].xyz);
  factor = sphereDensityFactor(sphere, nObject, normal);
  material = sphere.materialIndex;
  primitiveOffset = sphere.rayOffset;
}
