// The scene part of the secondary-ray offset. The whole policy is stated in gpu_types.h
// ("Secondary rays"); both backends take their numbers from there and from here.
#pragma once

#include "scene/scene_desc.h"

namespace vkrt {

// The scene's own length scale: the diagonal of the box around its triangles and spheres
// (0 without geometry).
double sceneSize(const SceneDesc& scene);

// sceneEpsilon: 1e-3 for a scene of the course's size, scaled by whole decades with the
// scene's size.
double secondaryRayEpsilon(const SceneDesc& scene);

// The offset of secondary rays from a hit point p given relative to the camera.
double secondaryRayTMin(double sceneEpsilon, const dvec3& pFromCamera);

}  // namespace vkrt
