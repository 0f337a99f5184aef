// layout_probe.comp: copies every struct of gpu_types.h, field by field, into a uint array, so
// a test can check that the shader reads exactly the bytes the host wrote.
#version 450
#extension GL_GOOGLE_include_directive : require

#include "gpu_types.h"

layout(local_size_x = 1) in;

layout(std430, binding = 0) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = 1) readonly buffer TriangleNormals { GpuTriangleNormals triangleNormals[]; };
layout(std430, binding = 2) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = 3) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = 4) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 5) readonly buffer BvhNodes { GpuBvhNode nodes[]; };
layout(std430, binding = 6) readonly buffer Params { GpuRenderParams params; };   // as both shaders read it
layout(std430, binding = 7) writeonly buffer Out { uint words[]; };
layout(std430, binding = 8) readonly buffer QuadLights { GpuQuadLight quadLights[]; };
layout(std430, binding = 9) readonly buffer PathParams { GpuPathParams pathParams; };   // as pathtrace.comp reads it
layout(std430, binding = 10) readonly buffer Emitters { GpuEmitter emitters[]; };
layout(std430, binding = 11) readonly buffer WhittedStates { GpuWhittedState whittedStates[]; };
layout(std430, binding = 12) readonly buffer PathTracerStates { GpuPathTracerState pathStates[]; };
layout(std430, binding = 13) readonly buffer Counters { GpuCounters counters[]; };
// pathtrace.comp's push constants, as std430 (the layout of a push constant block) in a buffer:
// a shader has one push constant block, and this probe's holds raytrace.comp's.
layout(std430, binding = 14) readonly buffer PathPush { GpuPathPush pathPush[]; };
layout(push_constant) uniform Push { GpuPushConstants pc; };   // as raytrace.comp reads it

uint n = 0u;
void put(float f) { words[n++] = floatBitsToUint(f); }
void put(uint u) { words[n++] = u; }
void put(vec4 v) { put(v.x); put(v.y); put(v.z); put(v.w); }
void put(GpuTraceState t) {
  put(t.origin); put(t.direction); put(t.hitPoint); put(t.hitNormal); put(t.shadowDir);
  put(t.hitB1); put(t.hitB2); put(t.shadowCos); put(t.phase);
  put(t.hitPrim); put(t.hitMaterial); put(t.lightIndex); put(t.stackSize);
  for (uint i = 0u; i < kTraversalStackSize; ++i) put(t.stack[i]);
  for (uint i = 0u; i < kTraversalStackSize; ++i) put(t.stackT[i]);
}

void main() {
  // Element 1 of each array, so that the array stride is checked as well as the offsets.
  GpuTriangle t = triangles[1];
  put(t.p0); put(t.p1); put(t.p2); put(t.materialIndex); put(t.normalsIndex); put(t.rayOffset); put(t.planeOffset);
  GpuTriangleNormals tn = triangleNormals[1];
  put(tn.n0); put(tn.n1); put(tn.n2);
  GpuSphere s = spheres[1];
  put(s.objectFromWorld[0]); put(s.objectFromWorld[1]); put(s.objectFromWorld[2]); put(s.objectFromWorld[3]);
  put(s.centerRadius); put(s.materialIndex); put(s.rayOffset); put(s.pad0); put(s.pad1);
  GpuLight l = lights[1];
  put(l.positionOrDirection); put(l.color); put(l.attenuation0); put(l.attenuation1); put(l.attenuation2); put(l.kind);
  GpuMaterial m = materials[1];
  put(m.ambient); put(m.diffuse); put(m.specular); put(m.emission);
  GpuBvhNode b = nodes[1];
  put(b.minX); put(b.minY); put(b.minZ); put(b.leftOrFirst); put(b.maxX); put(b.maxY); put(b.maxZ); put(b.primCount);
  // The render's parameters: the only element of their buffer.
  GpuRenderParams p = params;
  put(p.width); put(p.height); put(p.maxDepth); put(p.lightCount); put(p.stepBudget); put(p.bandHeight);
  put(p.tilesX); put(p.tileOrderStride); put(p.primCount); put(p.rootEntry);
  put(p.originX); put(p.originY); put(p.fullWidth); put(p.fullHeight); put(p.triangleCount); put(p.sphereCount);
  GpuQuadLight q = quadLights[1];
  put(q.corner); put(q.edgeAB); put(q.edgeAC); put(q.normal); put(q.radiance);
  GpuPathParams pp = pathParams;
  put(pp.camera.origin); put(pp.camera.right); put(pp.camera.up); put(pp.camera.back);
  put(pp.integrator); put(pp.nextEvent); put(pp.sampling); put(pp.russianRoulette);
  put(pp.maxDepth); put(pp.lightSamples); put(pp.lightStrata); put(pp.quadLightCount);
  put(pp.lightCount); put(pp.seed); put(pp.firstSample); put(pp.sampleCount);
  put(pp.jitter); put(pp.emitterCount); put(pp.emitterWeightScale); put(pp.strataSide);
  put(pp.pad0); put(pp.pad1); put(pp.pad2); put(pp.pad3);
  GpuEmitter e = emitters[1];
  put(e.primRef); put(e.cdf);
  GpuWhittedState w = whittedStates[1];
  put(w.throughput); put(w.radiance); put(w.lightColor); put(w.depth); put(w.tile); put(w.pad0); put(w.pad1);
  put(w.trace);
  GpuPathTracerState ps = pathStates[1];
  put(ps.throughput); put(ps.radiance); put(ps.pixelSum); put(ps.pending);
  put(ps.bounce); put(ps.sampleIndex); put(ps.tile); put(ps.pad0);
  put(ps.trace);
  GpuCounters c = counters[1];
  put(c.suspended); put(c.shadowRays); put(c.secondaryRays); put(c.nonFinite);
  put(c.finished); put(c.steps); put(c.boxTestsLow); put(c.boxTestsHigh); put(c.primitiveTestsLow);
  put(c.primitiveTestsHigh); put(c.pad0); put(c.pad1);
  GpuPathPush pp2 = pathPush[1];
  put(pp2.bandY0); put(pp2.resume); put(pp2.pad0); put(pp2.pad1);
  // The push constants: one block, not an array.
  put(pc.camera.origin); put(pc.camera.right); put(pc.camera.up); put(pc.camera.back);
  put(pc.cutoff.bound); put(pc.cutoff.specular); put(pc.bandY0); put(pc.resume); put(pc.pad0); put(pc.pad1);
}
