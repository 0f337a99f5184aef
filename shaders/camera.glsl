// camera.glsl: the camera ray of both compute shaders (raytrace.comp, pathtrace.comp).
// Include after params.glsl (`params`, GpuRenderParams).

// The unit direction of the camera ray through the point `offset` of pixel `pixel` ((0.5,
// 0.5) is its centre) of the full image, row 0 at the top (doc/scene-format.md, "Camera"): a
// crop's pixels are those of the whole image (GpuCamera).
vec3 cameraRayDirection(GpuCamera camera, uvec2 pixel, vec2 offset) {
  float a = (float(pixel.x) + offset.x) - 0.5 * float(params.fullWidth);
  float b = 0.5 * float(params.fullHeight) - (float(pixel.y) + offset.y);
  return normalize(a * camera.right.xyz + b * camera.up.xyz - camera.back.xyz);
}
