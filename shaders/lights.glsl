// lights.glsl: point and directional lights, as both compute shaders see them (raytrace.comp,
// pathtrace.comp). Include after the specialization constants kHasPointLights,
// kHasDirectionalLights and kHasAttenuation, and intersect.glsl.

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
