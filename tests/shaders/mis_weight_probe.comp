// mis_weight_probe.comp: evaluates pathtrace.comp's MIS weight (mis_weight.glsl) on pairs of
// densities, so that a test can check it against the closed form of the power heuristic.
#version 450
#extension GL_GOOGLE_include_directive : require

#include "../../shaders/mis_weight.glsl"

layout(local_size_x = 1) in;

layout(std430, binding = 0) readonly buffer Pairs { vec2 pairs[]; };   // (pdfThis, pdfOther)
layout(std430, binding = 1) writeonly buffer Weights { float weights[]; };

void main() {
  for (uint i = 0u; i < uint(pairs.length()); ++i) weights[i] = powerHeuristic(pairs[i].x, pairs[i].y);
}
