// normals.comp: the normals view (vkrt --view normals): each pixel's colour is the unit
// surface normal where its camera ray first hits, n * 0.5 + 0.5 (world axes x, y, z as red,
// green and blue), and black where it hits nothing. One deterministic sample a pixel on the
// Whitted host (whitted_host.glsl: its parameters, state and walk over the pixels).
// Its math is float32 and written independently of the CPU reference (host/cpu/normals.cpp).
#version 450
#extension GL_GOOGLE_include_directive : require

#include "gpu_types.h"
#include "scene_features.glsl"
#include "whitted_host.glsl"

vec3 color;   // the pixel's: black until its camera ray hits

void startPixel() {
  color = vec3(0.0);
  startCameraRay();
}
vec3 pixelColor() { return color; }

void beginShading() {
  surfaceAtHit();
  color = hitNormal * 0.5 + 0.5;
  phase = kPhaseEnd;
}

// No shadow rays and no lights: a view never enters these phases.
void onShadowResult(bool blocked) { phase = kPhaseEnd; }
void lightStep(inout uint step) { phase = kPhaseEnd; }

void saveTechniqueState(uint slot) { states[slot].radiance = vec4(color, 0.0); }
void loadTechniqueState(uint slot) { color = states[slot].radiance.rgb; }

#include "driver.glsl"   // main(): the step loop, suspension, the done marker, the counters
