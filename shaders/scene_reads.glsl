// scene_reads.glsl: how the compute shaders read the scene (raytrace.comp, pathtrace.comp):
// the bindings of gpu_render.h and one load function per struct. Include after gpu_types.h;
// depends on nothing else.
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
