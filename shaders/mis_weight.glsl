// The power heuristic (beta = 2) of doc/path-tracing.md, "Estimators": the weight of a sample drawn
// by the strategy of density pdfThis against the other strategy's pdfOther, both in solid
// angle. Written as 1 / (1 + (pdfOther / pdfThis)^2), the same as pdfThis^2 / (pdfThis^2 +
// pdfOther^2) without squaring a density that float32 may overflow. Included by
// pathtrace.comp and by the test probe that checks it against the closed form.
float powerHeuristic(float pdfThis, float pdfOther) {
  float ratio = pdfOther / pdfThis;
  return 1.0 / (1.0 + ratio * ratio);
}
