// driver.glsl: the one main() of every rendering technique (raytrace.comp, pathtrace.comp):
// the step loop, suspension and resumption, the done marker and the counters. Include last,
// after technique.glsl and the technique's hooks:
//
//   void copyTechniqueParams()   main's first lines: copy what the technique reads of its
//                                push constants or buffers into private variables
//   bool setPixel()              the lane's pixel of `tile`: whether it lies in the band (tile_run.glsl)
//   uint bandSlot()              the current pixel's place in pixels[]
//   void startFirstPixel()       the lane's first pixel of its run (its first ray, or kPhaseEnd)
//   void resumePixel()           after a suspended lane's state is loaded and its pixel set
//   void beginShading()          the current ray hit hitPrim at bestT
//   void onShadowResult(bool blocked)   the shadow ray's answer (then kPhaseLight)
//   void lightStep(inout uint step)     kPhaseLight: the next light (sample), or what follows
//   void endPath()               kPhaseEnd: the path is over; the next one, or kPhaseDone
//   void saveTechniqueState(uint slot), loadTechniqueState(uint slot)   its own of states[slot]
//
// Each hook has one call site: lavapipe inlines every call and runs each copy whenever it is
// reached by any lane of a vector.

// The traversal of the current ray (kPhaseTrace: nearest hit) or of a shadow ray
// (kPhaseShadow: any hit), as far as the step budget goes (traceRay); one function for both
// kinds, so that lanes of a SIMD vector in different phases run it once. Then what follows.
void traversalStep(inout uint step) {
  TracedRay r = tracedRay();
  bool blocked = traceRay(r, step);
  if (sp > 0u) return;   // out of steps: the next dispatch goes on from here
  ++step;                // what follows the traversal is a step of its own
  if (r.shadow) {
    onShadowResult(blocked);
  } else if (hitPrim != kNoHit) {
    beginShading();
  } else {
    phase = kPhaseEnd;   // a miss is black
  }
}

// ---- suspension: the traversal's state, the tile, and the technique's own ----------------------

void saveState(uint slot) {
  saveTrace(slot);
  states[slot].tile = tile;
  saveTechniqueState(slot);
}

void loadState(uint slot) {
  loadTrace(slot);
  tile = states[slot].tile;
  loadTechniqueState(slot);
}

void main() {
  loadParams();
  copyTechniqueParams();
  // The lanes share out the band's tiles in runs (tile_run.glsl).
  uint runStart = startRun();
  uint invocation = gl_WorkGroupID.x * gl_WorkGroupSize.x * gl_WorkGroupSize.y + gl_LocalInvocationIndex;

  // The lane's last pixel's w says whether the invocation is done: 1 once that pixel is
  // written, 0 from a suspension on (so that only suspended invocations touch the state buffer).
  if (!lastPixelOfRun(runStart)) return;   // no pixel of the band in this lane's tiles
  uint lastSlot = bandSlot();
  if (pc.resume != 0u) {
    if (pixels[lastSlot].w != 0.0) return;   // finished in an earlier round
    loadState(invocation);
    setPixel();
    resumePixel();
  } else {
    firstPixelOfRun(runStart);
    startFirstPixel();
  }

  // A ray's traversal and the light step after it share an iteration (lavapipe runs both
  // bodies for the vector whenever any lane needs either), and so do the end of a path and
  // the start of the next.
  uint step = 0u;
  for (; step < params.stepBudget && phase != kPhaseDone; ++step) {
    if (phase == kPhaseTrace || phase == kPhaseShadow) traversalStep(step);
    if (phase == kPhaseLight) lightStep(step);
    if (phase == kPhaseEnd) endPath();
  }

  steps = step;
  addCounts(phase != kPhaseDone);
  if (phase != kPhaseDone) {
    saveState(invocation);
    pixels[lastSlot].w = 0.0;   // (stale from an earlier band, or 0 already)
  }
}
