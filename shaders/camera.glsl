// camera.glsl: the camera ray of both compute shaders (raytrace.comp, pathtrace.comp).
// Include after the uniform `params` (GpuRenderParams).

// The unit direction of the camera ray through the point `offset` of pixel `pixel` ((0.5,
// 0.5) is its centre) of the full image, row 0 at the top (doc/scene-format.md, "Camera"): a
// crop's pixels are those of the whole image. right and up span one pixel; back points from
// the look-at point to the eye (GpuPushConstants, GpuPathParams).
vec3 cameraRayDirection(uvec2 pixel, vec2 offset, vec3 right, vec3 up, vec3 back) {
  float a = (float(pixel.x) + offset.x) - 0.5 * float(params.fullWidth);
  float b = 0.5 * float(params.fullHeight) - (float(pixel.y) + offset.y);
  return normalize(a * right + b * up - back);
}
