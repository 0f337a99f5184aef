// traverse.glsl: the skeleton both compute shaders share (raytrace.comp, pathtrace.comp): the
// current ray and its nearest hit, the shadow ray of a light, the traversal stack, one BVH
// descent as a bounded number of steps or the test of every primitive of a small scene
// (traceRay), and the save and load of all that (GpuTraceState)
// when an invocation runs out of steps. What a shader does with a hit, a miss or a shadow
// ray's answer stays in the shader.
// Include after intersect.glsl, params.glsl (`params`, GpuRenderParams) and the buffer
// `states[]`, whose elements hold a GpuTraceState named `trace`.

// ---- the state of the ray being traced (registers; saved to states[].trace on suspension) ----
vec3 rayOrigin, rayDir;   // the current ray (camera, mirror or scattered)
float rayTMin;
float bestT, bestB1, bestB2;   // its nearest hit so far: t and barycentric weights of p1 and p2
uint hitPrim;                  // that hit's primRef, or kNoHit
vec3 hitPoint, hitNormal;      // the shaded hit (and hitTMin, hitGrazing: intersect.glsl)
uint hitMaterial;
vec3 shadowDir;                // the shadow ray leaving hitPoint toward a light
float shadowTMax, shadowCos;   // its reach, and N . shadowDir
uint phase, lightIndex;

// The traversal stack of the ray being traced. A local array is per-lane scratch memory in
// llvmpipe; its size must be a constant.
uint sp;
uint stack[kTraversalStackSize];     // entries (kStackLeafBit) of nodes whose boxes the ray enters
float stackT[kTraversalStackSize];   // the entry distance of each, to skip it once a nearer hit is known

// The stack holds the root alone; an empty scene's root is an empty leaf: nothing to visit.
void startTraversal() {
  sp = params.primCount > 0u ? 1u : 0u;
  stack[0] = params.rootEntry;
  stackT[0] = 0.0;
}

// Starts the nearest-hit traversal of a ray (kPhaseTrace).
void startRay(vec3 origin, vec3 dir, float tMin) {
  rayOrigin = origin;
  rayDir = dir;
  rayTMin = tMin;
  bestT = kInfinity;
  hitPrim = kNoHit;
  startTraversal();
  phase = kPhaseTrace;
}

// Starts the any-hit traversal of the shadow ray leaving hitPoint along dir up to tMax, where
// N . dir = cosine (kPhaseShadow).
void startShadowTraversal(vec3 dir, float tMax, float cosine) {
  shadowDir = dir;
  shadowTMax = tMax;
  shadowCos = cosine;
  startTraversal();
  phase = kPhaseShadow;
}

// The ray that phase kPhaseTrace (the current ray, up to its nearest hit so far) or
// kPhaseShadow (the shadow ray) traces.
struct TracedRay {
  bool shadow;
  vec3 origin, dir;
  float tMin, tMax;
};

TracedRay tracedRay() {
  TracedRay r;
  r.shadow = phase == kPhaseShadow;
  r.origin = r.shadow ? hitPoint : rayOrigin;
  r.dir = r.shadow ? shadowDir : rayDir;
  r.tMin = r.shadow ? secondaryTMin(shadowCos) : rayTMin;
  r.tMax = r.shadow ? shadowTMax : bestT;
  return r;
}

// A child of a node block: its stack entry, and where the ray enters its box (kInfinity: it
// does not, or the child is unused).
struct ChildHit {
  uint entry;
  float t;
};

ChildHit childHit(uint node, TracedRay r, vec3 invDir, float tMax) {
  GpuBvhNode n = loadNode(node);
  ChildHit c;
  c.entry = stackEntry(n);
  c.t = c.entry == 0u ? kInfinity : boxEntry(n, r.origin, invDir, r.tMin, tMax);
  return c;
}

// Orders two children nearer first (a tie keeps their order).
void nearerFirst(inout ChildHit a, inout ChildHit b) {
  bool swap = b.t < a.t;
  ChildHit lo = swap ? b : a, hi = swap ? a : b;
  a = lo;
  b = hi;
}

void pushChild(ChildHit c) {
  if (c.t != kInfinity) {
    stack[sp] = c.entry;
    stackT[sp++] = c.t;
  }
}

// The BVH traversal of ray r from the stack as it stands, as far as the step budget goes:
// interior nodes down to a leaf, then that leaf's primitives, until the stack is empty (Aila
// and Laine's while-while loop). A nearest-hit ray updates bestT, hitPrim, bestB1 and bestB2;
// a shadow ray stops at its first hit, and the result says whether there was one. Out of
// steps, sp > 0 and the stack holds where the next dispatch goes on. Each node is a step of
// the budget. lavapipe runs the lanes of a SIMD vector through every branch of the loop body
// that any of them takes, so a whole traversal stays inside this loop: the shading code
// outside runs once per ray, not once per leaf.
bool traverseBvh(TracedRay r, inout uint step) {
  float tMax = r.tMax;
  vec3 invDir = safeInverse(r.dir);
  Shear sh;
  if (kHasTriangles) sh = shearFor(r.dir);
  bool blocked = false;
  while (sp > 0u && step < params.stepBudget) {
    // Pop an entry; those entered beyond the nearest hit so far (visit false) are popped past
    // in this loop of their own, not each in a pass of the whole walk (fewer instructions:
    // bench/README.md, "The walk's pops"). Each pop is a step.
    uint entry;
    float entryT;
    bool visit;
    do {
      --sp;
      ++step;
      entry = stack[sp];
      entryT = stackT[sp];
      visit = entryT < tMax;
    } while (!visit && sp > 0u && step < params.stepBudget);
    // Down interior nodes: the nearer child the ray enters is the next node (in registers),
    // the farther one is pushed; the order of visits is that of pushing both. Each node
    // entered is a step.
    while (!kWideBvh && visit && (entry & kStackLeafBit) == 0u && step < params.stepBudget) {
      GpuBvhNode left = loadNode(entry), right = loadNode(entry + 1u);
      boxTests += 2u;
      float tl = boxEntry(left, r.origin, invDir, r.tMin, tMax);
      float tr = boxEntry(right, r.origin, invDir, r.tMin, tMax);
      bool leftFirst = tl <= tr;
      float tNear = leftFirst ? tl : tr, tFar = leftFirst ? tr : tl;
      if (tFar != kInfinity) {
        stack[sp] = stackEntry(leftFirst ? right : left);
        stackT[sp++] = tFar;
      }
      visit = tNear != kInfinity;
      entry = stackEntry(leftFirst ? left : right);
      entryT = tNear;
      if (visit) ++step;
    }
    // Down interior nodes (blocks of four children, some unused: entry 0): the nearest child the
    // ray enters is the next node (in registers), the others it enters are pushed, farthest
    // first. Each node entered is a step.
    while (kWideBvh && visit && (entry & kStackLeafBit) == 0u && step < params.stepBudget) {
      ChildHit c0 = childHit(entry, r, invDir, tMax), c1 = childHit(entry + 1u, r, invDir, tMax);
      ChildHit c2 = childHit(entry + 2u, r, invDir, tMax), c3 = childHit(entry + 3u, r, invDir, tMax);
      boxTests += 4u;
      nearerFirst(c0, c1);
      nearerFirst(c2, c3);
      nearerFirst(c0, c2);
      nearerFirst(c1, c3);
      nearerFirst(c1, c2);
      pushChild(c3);
      pushChild(c2);
      pushChild(c1);
      visit = c0.t != kInfinity;
      entry = c0.entry;
      entryT = c0.t;
      if (visit) ++step;
    }
    if (!visit) continue;
    if ((entry & kStackLeafBit) == 0u) {   // out of steps: the node waits on the stack
      stack[sp] = entry;
      stackT[sp++] = entryT;
      break;
    }
    uint first = entry & kStackFirstMask, count = (entry >> kStackCountShift) & 7u;
    primitiveTests += count;
    for (uint i = 0u; i < count; ++i) {
      uint ref = loadPrimRef(first + i);
      vec2 b;
      float t = hitPrimitive(ref, r.origin, r.dir, sh, r.tMin, tMax, b);
      if (t > 0.0) {
        if (r.shadow) {
          blocked = true;
          break;
        }
        tMax = t;
        bestT = t;
        hitPrim = ref;
        bestB1 = b.x;
        bestB2 = b.y;
      }
    }
    if (blocked) {
      sp = 0u;
      break;
    }
  }
  return blocked;
}

// ---- suspension ----------------------------------------------------------------------------------

void saveTrace(uint slot) {
  states[slot].trace.origin = vec4(rayOrigin, rayTMin);
  states[slot].trace.direction = vec4(rayDir, bestT);
  states[slot].trace.hitPoint = vec4(hitPoint, hitTMin);
  states[slot].trace.hitNormal = vec4(hitNormal, hitGrazing);
  states[slot].trace.shadowDir = vec4(shadowDir, shadowTMax);
  states[slot].trace.hitB1 = bestB1;
  states[slot].trace.hitB2 = bestB2;
  states[slot].trace.shadowCos = shadowCos;
  states[slot].trace.phase = phase;
  states[slot].trace.hitPrim = hitPrim;
  states[slot].trace.hitMaterial = hitMaterial;
  states[slot].trace.lightIndex = lightIndex;
  states[slot].trace.stackSize = sp;
  for (uint i = 0u; i < sp; ++i) {
    states[slot].trace.stack[i] = stack[i];
    states[slot].trace.stackT[i] = stackT[i];
  }
}

void loadTrace(uint slot) {
  rayOrigin = states[slot].trace.origin.xyz;
  rayTMin = states[slot].trace.origin.w;
  rayDir = states[slot].trace.direction.xyz;
  bestT = states[slot].trace.direction.w;
  hitPoint = states[slot].trace.hitPoint.xyz;
  hitTMin = states[slot].trace.hitPoint.w;
  hitNormal = states[slot].trace.hitNormal.xyz;
  hitGrazing = states[slot].trace.hitNormal.w;
  shadowDir = states[slot].trace.shadowDir.xyz;
  shadowTMax = states[slot].trace.shadowDir.w;
  bestB1 = states[slot].trace.hitB1;
  bestB2 = states[slot].trace.hitB2;
  shadowCos = states[slot].trace.shadowCos;
  phase = states[slot].trace.phase;
  hitPrim = states[slot].trace.hitPrim;
  hitMaterial = states[slot].trace.hitMaterial;
  lightIndex = states[slot].trace.lightIndex;
  sp = states[slot].trace.stackSize;
  for (uint i = 0u; i < sp; ++i) {
    stack[i] = states[slot].trace.stack[i];
    stackT[i] = states[slot].trace.stackT[i];
  }
}

// The nearest hit within (tMin, tMax) among all primitives (bestT, hitPrim, bestB1, bestB2),
// or with `shadow` whether any blocks the ray. The loop index is the same in every lane.
bool testAll(vec3 origin, vec3 dir, Shear sh, float tMin, float tMax, bool shadow) {
  float nearest = tMax;
  uint prim = kNoHit;
  vec2 bary = vec2(0.0);
  if (kHasTriangles) {
    for (uint i = 0u; i < params.triangleCount; ++i) {
      vec2 b;
      float t = hitTriangleWhole(i, origin, dir, sh, tMin, nearest, b);
      bool hit = t > 0.0;
      nearest = hit ? t : nearest;
      prim = hit ? i : prim;
      bary = hit ? b : bary;
    }
  }
  if (kHasSpheres) {
    for (uint i = 0u; i < params.sphereCount; ++i) {
      float t = hitSphere(i, origin, dir, tMin, nearest);
      bool hit = t > 0.0;
      nearest = hit ? t : nearest;
      prim = hit ? primRef(kPrimSphere, i) : prim;
      bary = hit ? vec2(0.0) : bary;
    }
  }
  if (shadow || prim == kNoHit) return prim != kNoHit;
  bestT = nearest;
  hitPrim = prim;
  bestB1 = bary.x;
  bestB2 = bary.y;
  return false;
}

// The ray `r` traced as far as the step budget goes: with kTestAll against every primitive of
// the scene (testAll), the whole ray in one go, else the walk of the BVH (traverseBvh). The
// result and the suspension (sp > 0) as traverseBvh's: a tested ray that waits for the next
// dispatch returns with sp as startTraversal left it, 1 (0 only in a scene without
// primitives, whose ray then misses at once, as testing it would find).
bool traceRay(TracedRay r, inout uint step) {
  if (!kTestAll) return traverseBvh(r, step);
  // Every primitive, as one step per kMaxLeafPrims of them; a ray is never left half-tested,
  // so it waits for the next dispatch unless the steps left suffice or the dispatch just began.
  uint cost = max(1u, (params.triangleCount + params.sphereCount + kMaxLeafPrims - 1u) / kMaxLeafPrims);
  if (step > 0u && step + cost > params.stepBudget) return false;
  step += cost - 1u;
  sp = 0u;
  Shear sh;
  if (kHasTriangles) sh = shearFor(r.dir);
  return testAll(r.origin, r.dir, sh, r.tMin, r.tMax, r.shadow);
}
