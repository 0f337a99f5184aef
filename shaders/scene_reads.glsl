// scene_reads.glsl: how the compute shaders read the scene (raytrace.comp, pathtrace.comp):
// the bindings of gpu_render.h and one load function per struct, but the shapes' (their own
// files: shapes/*.glsl). Include after gpu_types.h; depends on nothing else.
// Scene reads: storage buffers, or (VKRT_TEXEL_READS) the same bytes through uint texel-buffer
// views, which lavapipe reads 2.7-3x faster inside loops (bench/ measures both). Only uint
// views: a float view may flush denormal-looking indices or canonicalise NaN-looking words.
#ifdef VKRT_TEXEL_READS
layout(binding = kBindingLights) uniform usamplerBuffer lightWords;           // RGBA32UI, 3 texels each
layout(binding = kBindingMaterials) uniform usamplerBuffer materialWords;        // RGBA32UI, 4 texels each
layout(binding = kBindingBvhNodes) uniform usamplerBuffer nodeWords;            // RGBA32UI, 2 texels each
layout(binding = kBindingPrimRefs) uniform usamplerBuffer primRefWords;         // R32UI

vec4 texelF(usamplerBuffer b, uint i) { return uintBitsToFloat(texelFetch(b, int(i))); }

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
layout(std430, binding = kBindingLights) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = kBindingMaterials) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = kBindingBvhNodes) readonly buffer BvhNodes { GpuBvhNode nodes[]; };
layout(std430, binding = kBindingPrimRefs) readonly buffer PrimRefs { uint primRefs[]; };

GpuLight loadLight(uint i) { return lights[i]; }
GpuMaterial loadMaterial(uint i) { return materials[i]; }
GpuBvhNode loadNode(uint i) { return nodes[i]; }
uint loadPrimRef(uint i) { return primRefs[i]; }
#endif
