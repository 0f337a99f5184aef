// counters.glsl: what both compute shaders count for the host (GpuCounters; RayCounts there):
// the rays each lane traced in this dispatch, the pixels (raytrace.comp) or samples
// (pathtrace.comp) whose radiance came out NaN or infinite, and the invocations or pixels
// that ran out of steps. Include after gpu_types.h.

layout(std430, binding = kBindingCounters) buffer Counters { GpuCounters counters; };

uint shadowRays = 0u;
uint secondaryRays = 0u;   // mirror (raytrace.comp) or scattered (pathtrace.comp) rays
uint nonFinite = 0u;

// Adds the lane's counts to the dispatch's (one atomic each, and none for a lane with nothing
// to add), and the lane as suspended when it is.
void addCounts(bool suspended) {
  if (shadowRays + secondaryRays + nonFinite > 0u) {
    atomicAdd(counters.shadowRays, shadowRays);
    atomicAdd(counters.secondaryRays, secondaryRays);
    atomicAdd(counters.nonFinite, nonFinite);
  }
  if (suspended) atomicAdd(counters.suspended, 1u);
}
