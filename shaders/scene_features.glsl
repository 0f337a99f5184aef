// scene_features.glsl: the specialization constants both compute shaders give the same
// meaning (gpu_render.h, kSpec*): what the scene contains, so that the driver compiles out the
// code of what it lacks. Each shader declares its own after these (gpu_whitted.h, gpu_path.h).
layout(constant_id = kSpecHasTriangles) const bool kHasTriangles = true;
layout(constant_id = kSpecHasSpheres) const bool kHasSpheres = true;
layout(constant_id = kSpecHasSmoothNormals) const bool kHasSmoothNormals = true;
layout(constant_id = kSpecHasPointLights) const bool kHasPointLights = true;
layout(constant_id = kSpecHasDirectionalLights) const bool kHasDirectionalLights = true;
layout(constant_id = kSpecHasAttenuation) const bool kHasAttenuation = true;
layout(constant_id = kSpecTestAll) const bool kTestAll = false;
layout(constant_id = kSpecWideBvh) const bool kWideBvh = false;
