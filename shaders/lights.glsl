// lights.glsl: point and directional lights, as both compute shaders see them (raytrace.comp,
// pathtrace.comp): their read (GpuLight, by texels or from a storage buffer, as
// scene_reads.glsl reads the other structs) and what reaches a point from one. Its host side
// is host/scene/light.h. Include after the specialization constants kHasPointLights,
// kHasDirectionalLights and kHasAttenuation, scene_reads.glsl and intersect.glsl.

#ifdef VKRT_TEXEL_READS
SCENE_TEXELS(kBindingLights) lightWords;   // kLightTexels each
GpuLight loadLight(uint i) {
  const uint n = kLightTexels;
  GpuLight l;
  l.positionOrDirection = texelF(lightWords, n * i);
  l.color = texelF(lightWords, n * i + 1u);
  uvec4 c = texelU(lightWords, n * i + 2u);
  l.attenuation0 = uintBitsToFloat(c.x);
  l.attenuation1 = uintBitsToFloat(c.y);
  l.attenuation2 = uintBitsToFloat(c.z);
  l.kind = c.w;
  return l;
}
#else
layout(std430, binding = kBindingLights) readonly buffer Lights { GpuLight lights[]; };
GpuLight loadLight(uint i) { return lights[i]; }
#endif

// From point p toward light `light`: the unit direction; `reach`, how far its shadow ray goes
// (the light's distance; kInfinity for a directional light); and `arriving`, the light's
// colour over the attenuation divisor c0 + c1 d + c2 d^2 (doc/scene-format.md, "Shading"),
// kept finite even for a tiny divisor, so that a zero material term times it stays 0, not
// NaN. A directional light's direction is a unit vector already (the host's, rounded to float).
vec3 towardLight(GpuLight light, vec3 p, out float reach, out vec3 arriving) {
  reach = kInfinity;
  float divisor = 1.0;
  vec3 dir = light.positionOrDirection.xyz;
  if (kHasPointLights && (!kHasDirectionalLights || light.kind == kLightPoint)) {
    vec3 v = light.positionOrDirection.xyz - p;
    float distance = length(v);
    dir = v / distance;
    reach = distance;
    if (kHasAttenuation)
      divisor = light.attenuation0 + light.attenuation1 * distance + light.attenuation2 * distance * distance;
  }
  arriving = clamp(light.color.rgb / divisor, -kInfinity, kInfinity);
  return dir;
}
