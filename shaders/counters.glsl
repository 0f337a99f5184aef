// counters.glsl: what both compute shaders count for the host (GpuCounters; RayCounts there):
// the rays each lane traced in this dispatch, the pixels (raytrace.comp) or samples
// (pathtrace.comp) whose radiance came out NaN or infinite, the pixels or samples finished,
// the steps run, and the invocations or pixels that ran out of steps. Include after gpu_types.h.

layout(std430, binding = kBindingCounters) buffer Counters { GpuCounters counters; };

uint shadowRays = 0u;
uint secondaryRays = 0u;   // mirror (raytrace.comp) or scattered (pathtrace.comp) rays
uint nonFinite = 0u;
uint finished = 0u;        // pixels (raytrace.comp) or samples (pathtrace.comp) finished
uint steps = 0u;           // state-machine steps run in this dispatch (pathtrace.comp)

// Adds the lane's counts to the dispatch's (one atomic each, and none for a lane with nothing
// to add), and the lane as suspended when it is.
void addCounts(bool suspended) {
  if (shadowRays + secondaryRays + nonFinite + finished > 0u) {
    atomicAdd(counters.shadowRays, shadowRays);
    atomicAdd(counters.secondaryRays, secondaryRays);
    atomicAdd(counters.nonFinite, nonFinite);
    atomicAdd(counters.finished, finished);
  }
  if (steps > 0u) atomicAdd(counters.steps, steps);
  if (suspended) atomicAdd(counters.suspended, 1u);
}
