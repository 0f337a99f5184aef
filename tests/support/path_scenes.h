// Scenes for the path integrators' tests, built as SceneDesc values (no parser): quads, quad
// lights, a white furnace and a small Cornell-like box; and the statistics the tests share.
#pragma once

#include <cstdint>
#include <vector>

#include "image/radiance_image.h"
#include "scene/scene_desc.h"

namespace vkrt::test {

// Adds a material and returns its index.
std::uint32_t addMaterial(SceneDesc& scene, const Material& m);

// The parallelogram a, a+ab, a+ab+ac, a+ac as two flat triangles whose face normal is
// normalize(cross(ac, ab)) (the side a quad light emits on).
void addQuad(SceneDesc& scene, const dvec3& a, const dvec3& ab, const dvec3& ac, std::uint32_t material);

// `quadLight a ab ac L` as the parser makes it (scene/finish_scene.h): the light, its own
// material and its two triangles, facing cross(ac, ab).
void addQuadLight(SceneDesc& scene, const dvec3& a, const dvec3& ab, const dvec3& ac, const dvec3& radiance);

// A camera at `from` looking at `at`, image w x h.
void setCamera(SceneDesc& scene, const dvec3& from, const dvec3& at, double fovyDegrees, int w, int h);

// The cube [-1, 1]^3 seen from its centre, every face turned inward, diffuse `albedo` and
// emitting `emission`: every point's radiance is emission / (1 - albedo) (maxdepth -1), or
// emission (1 + a + ... + a^D) with maxdepth D.
SceneDesc furnaceBox(double albedo, double emission, int size);

// A Cornell-like box (2 x 2 x 2, open at the front) lit by a quad light under its ceiling,
// with a Phong-glossy block and a GGX sphere; w x h pixels, pathtracer, maxdepth `maxDepth`.
SceneDesc cornellLikeBox(int size, int maxDepth);

// The same box lit instead by emissive surfaces (`emission`, no quad light): an ellipsoid
// (a sphere under a rotation and a non-uniform scale) under the ceiling and a triangle before
// the back wall, for next-event estimation of emissive triangles and spheres.
SceneDesc emissiveSurfacesBox(int size, int maxDepth);

// Direct lighting where MIS matters: a large quad light close above a floor of a Phong half
// and a GGX half, seen from below the light's plane; maxdepth 1.
SceneDesc glossyFloorUnderLargeLight(int size);

// A diffuse floor beside a near-mirror Phong sphere (shininess 1000, ks 0.8, kd 0.2) and a
// 0.6 x 0.6 quad light half a unit to its side, facing it: the floor behind the light's plane
// (x < -1) is lit only through the sphere (light -> sphere -> floor); seen from beyond the
// light, with the sphere and the lit floor at the top of the image. pathtracer, maxdepth
// `maxDepth`.
SceneDesc floorBesideMirrorSphere(int size, int maxDepth);

// The two-sided p-value of Welch's t-test for means m1, m2 with variances of the means
// v1, v2 (already divided by their counts) and counts n1, n2.
double welchPValue(double m1, double v1, int n1, double m2, double v2, int n2);

// The two-sided tail probability of Student's t with `dof` degrees of freedom beyond |t|.
double studentTwoSidedTail(double t, double dof);

}  // namespace vkrt::test
