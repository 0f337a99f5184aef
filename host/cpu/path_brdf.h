// The BRDFs of the path integrators and how their directions are sampled (doc/path-tracing.md,
// "BRDFs", and doc/design.md, "Random numbers and sampling rules"), in double precision.
// Pure functions of a material and unit vectors; knows nothing of scenes or rays.
#pragma once

#include "scene/scene_desc.h"

namespace vkrt {

// f(w_i, w_o) at a point of normal n (all unit; w_o toward the viewer, w_i toward the light):
// modified Phong or GGX by m.brdf, 0 unless n.w_i > 0 and n.w_o > 0.
dvec3 evalBrdf(const Material& m, const dvec3& n, const dvec3& wi, const dvec3& wo);

// The GGX normal distribution D(h) for cos(theta_h) = nDotH (0 when alpha or nDotH is 0).
double ggxD(double alpha, double nDotH);

// The probability with which `sampling` picks the specular lobe: t of doc/path-tracing.md
// section 4 (Phong: avg(ks) / (avg(kd) + avg(ks)), 0 for a black material; GGX: at least 0.25).
double specularLobeProbability(const Material& m);

// The solid-angle density with which sampleDirection() draws w_i (0 below the surface).
double directionPdf(Sampling sampling, const Material& m, const dvec3& n, const dvec3& wi, const dvec3& wo);

// The direction drawn from the vertex's numbers u, v (direction slots) and lobe (kRngSlotLobe,
// used by Sampling::Brdf only). It may point below the surface (then f = 0 there).
dvec3 sampleDirection(Sampling sampling, const Material& m, const dvec3& n, const dvec3& wo, double u, double v,
                      double lobe);

// The power heuristic (beta = 2, doc/path-tracing.md, "Estimators"): the MIS weight of a sample
// drawn by the strategy of density pdfThis against the other strategy's pdfOther,
// pdfThis^2 / (pdfThis^2 + pdfOther^2); 0 when both are 0.
double powerHeuristic(double pdfThis, double pdfOther);

// The frame's vectors around unit axis n (gpu_types.h): local (x, y, z) is x t + y b + z n.
void frameAround(const dvec3& n, dvec3& t, dvec3& b);

}  // namespace vkrt
