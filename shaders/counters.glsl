// counters.glsl: what both compute shaders count for the host (GpuCounters; RayCounts there):
// the rays each lane traced in this dispatch, the pixels (raytrace.comp) or samples
// (pathtrace.comp) whose radiance came out NaN or infinite, the pixels or samples finished,
// the steps run, the BVH walk's box and primitive tests, and the invocations or pixels that
// ran out of steps. Include after gpu_types.h.

layout(std430, binding = kBindingCounters) buffer Counters { GpuCounters counters; };

uint shadowRays = 0u;
uint secondaryRays = 0u;   // mirror (raytrace.comp) or scattered (pathtrace.comp) rays
uint nonFinite = 0u;
uint finished = 0u;        // pixels (raytrace.comp) or samples (pathtrace.comp) finished
uint steps = 0u;           // state-machine steps run in this dispatch
uint boxTests = 0u;        // the BVH walk's child boxes tested (traverse.glsl)
uint primitiveTests = 0u;  // and its leaves' primitives tested

// Adds `n` to the 64-bit count of words `low` and `high`: an add that wraps the low word
// carries one into the high word (each such add sees the wrap in the value it replaced).
#define ADD_COUNT64(low, high, n)                   \
  if ((n) > 0u) {                                  \
    uint before = atomicAdd(low, n);               \
    if (before + (n) < before) atomicAdd(high, 1u); \
  }

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
  ADD_COUNT64(counters.boxTestsLow, counters.boxTestsHigh, boxTests)
  ADD_COUNT64(counters.primitiveTestsLow, counters.primitiveTestsHigh, primitiveTests)
  if (suspended) atomicAdd(counters.suspended, 1u);
}
