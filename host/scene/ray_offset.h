// The scene part of the secondary-ray offset. The whole policy is stated in gpu_types.h
// ("Secondary rays"); both backends take their numbers from there and from here.
#pragma once

#include "scene/scene_desc.h"

namespace vkrt {

// The box around the scene's triangles and spheres; false (and nothing set) without geometry.
bool sceneBounds(const SceneDesc& scene, dvec3& lo, dvec3& hi);

// The scene's own length scale: the diagonal of that box (0 without geometry).
double sceneSize(const SceneDesc& scene);

// sceneEpsilon: 1e-3 for a scene of the course's size, scaled by whole decades with the
// scene's size.
double secondaryRayEpsilon(const SceneDesc& scene);

// The offset of secondary rays from a hit point p given relative to the camera.
double secondaryRayTMin(double sceneEpsilon, const dvec3& pFromCamera);

}  // namespace vkrt
