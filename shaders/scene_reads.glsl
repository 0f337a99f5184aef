// scene_reads.glsl: how the compute shaders read the scene (raytrace.comp, pathtrace.comp):
// the bindings of gpu_render.h and one load function per struct, but the shapes' (their own
// files: shapes/*.glsl) and the lights' (lights.glsl). Include after gpu_types.h; depends on nothing else.
// Scene reads: storage buffers, or (VKRT_TEXEL_READS) the same bytes through uint texel-buffer
// views, which lavapipe reads faster (bench/README.md, "Tried and not kept": storage-buffer
// reads). Only uint views: a float view may flush denormal-looking indices or canonicalise
// NaN-looking words. The views are storage texel buffers read with imageLoad, which lavapipe
// inlines; a uniform texel buffer's texelFetch is a call of a texture function for each texel
// (bench/README.md, "Texel reads inlined"). Macros, since an image cannot be a function
// argument here.
#ifdef VKRT_TEXEL_READS
// A scene array as RGBA32UI texels (the primitive references as R32UI).
#define SCENE_TEXELS(b) layout(binding = b, rgba32ui) uniform readonly restrict uimageBuffer
#define texelU(b, i) imageLoad(b, int(i))
#define texelF(b, i) uintBitsToFloat(texelU(b, i))
SCENE_TEXELS(kBindingMaterials) materialWords;   // 4 texels each
SCENE_TEXELS(kBindingBvhNodes) nodeWords;        // 2 texels each
layout(binding = kBindingPrimRefs, r32ui) uniform readonly restrict uimageBuffer primRefWords;

GpuMaterial loadMaterial(uint i) {
  GpuMaterial m;
  m.ambient = texelF(materialWords, 4u * i);
  m.diffuse = texelF(materialWords, 4u * i + 1u);
  m.specular = texelF(materialWords, 4u * i + 2u);
  m.emission = texelF(materialWords, 4u * i + 3u);
  return m;
}
GpuBvhNode loadNode(uint i) {
  uvec4 a = texelU(nodeWords, 2u * i), b = texelU(nodeWords, 2u * i + 1u);
  GpuBvhNode n;
  n.minX = uintBitsToFloat(a.x); n.minY = uintBitsToFloat(a.y); n.minZ = uintBitsToFloat(a.z);
  n.leftOrFirst = a.w;
  n.maxX = uintBitsToFloat(b.x); n.maxY = uintBitsToFloat(b.y); n.maxZ = uintBitsToFloat(b.z);
  n.primCount = b.w;
  return n;
}
uint loadPrimRef(uint i) { return texelU(primRefWords, i).x; }
#else
layout(std430, binding = kBindingMaterials) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = kBindingBvhNodes) readonly buffer BvhNodes { GpuBvhNode nodes[]; };
layout(std430, binding = kBindingPrimRefs) readonly buffer PrimRefs { uint primRefs[]; };

GpuMaterial loadMaterial(uint i) { return materials[i]; }
GpuBvhNode loadNode(uint i) { return nodes[i]; }
uint loadPrimRef(uint i) { return primRefs[i]; }
#endif
