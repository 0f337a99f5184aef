// technique.glsl: what every rendering technique's compute shader declares (raytrace.comp,
// pathtrace.comp): the workgroup, the shared specialization constants, the band's pixels and
// suspended states, the render's parameters, the counters, the scene and its traversal, the
// camera, point and directional lights, and how a band's tiles are shared out. A technique
// includes it after gpu_types.h, its own specialization constants and its push constants
// (named `pc`, with bandY0), with TechniqueState defined as its suspended state (a struct of
// gpu_*.h with a GpuTraceState `trace` and a `tile`); then its own steps, and driver.glsl last.

layout(local_size_x = kWorkgroupSize, local_size_y = kWorkgroupSize) in;

// rgb: the technique's result for the pixel (radiance, or a sum of samples); w: 1 once the
// pixel is done, 0 while suspended (driver.glsl).
layout(std430, binding = kBindingPixels) buffer Pixels { vec4 pixels[]; };
layout(std430, binding = kBindingPathStates) buffer States { TechniqueState states[]; };   // one per invocation

#include "params.glsl"
#include "counters.glsl"
#include "scene_reads.glsl"
#include "intersect.glsl"
#include "traverse.glsl"
#include "camera.glsl"
#include "lights.glsl"
#include "tile_run.glsl"   // tile, runEnd, bandRows
