// whitted_host.glsl: what every shader that the Whitted host (gpu/vulkan_renderer) runs shares:
// raytrace.comp and the views (normals.comp). Its push constants (GpuPushConstants: the
// camera, the exactness cut-off) and suspended state (GpuWhittedState), technique.glsl's
// declarations, and one deterministic sample a pixel: the lane walks its run of tiles, the
// same pixel of each tile in turn (tile_run.glsl shares out the runs), tracing a camera ray
// through each pixel's centre. It gives driver.glsl's copyTechniqueParams, setPixel,
// bandSlot, startFirstPixel, resumePixel and endPath; the shader gives startPixel (the
// pixel's first ray, startCameraRay) and pixelColor (the colour endPath writes). Include after
// gpu_types.h and the shader's specialization constants.

// The push constants are copied, into the private `pc` (fewer instructions than reads where
// used: bench/README.md, "Parameters in storage buffers").
layout(push_constant) uniform Push { GpuPushConstants pcStored; };
GpuPushConstants pc;
void copyTechniqueParams() { pc = pcStored; }

#define TechniqueState GpuWhittedState
#include "technique.glsl"   // pixels[] (rgb: the pixel's colour), states[], the scene, traversal, tiles

uint pixelX, pixelY;   // the lane's pixel's column and row in the band (not saved: tile tells them)

// The lane's pixel in `tile`: whether it lies inside the band (the last tiles of a row or of
// the band may stick out).
bool setPixel() {
  pixelX = (tile % params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.x;
  pixelY = (tile / params.tilesX) * kWorkgroupSize + gl_LocalInvocationID.y;
  return pixelX < params.width && pixelY < bandRows;
}
uint bandSlot() { return pixelY * params.width + pixelX; }

// The camera ray through the pixel's centre, in the full image's pixel coordinates, started.
void startCameraRay() {
  uvec2 pixel = uvec2(pixelX + params.originX, pc.bandY0 + pixelY + params.originY);
  startRay(pc.camera.origin.xyz, cameraRayDirection(pc.camera, pixel, vec2(0.5)), 0.0);
}

// The surface where the current ray hit (hitPrim at bestT): hitPoint, hitNormal, hitMaterial.
void surfaceAtHit() {
  hitPoint = rayOrigin + bestT * rayDir;
  surfaceAt(hitPrim, rayOrigin, rayDir, bestT, vec2(bestB1, bestB2), hitPoint, pc.camera.origin.xyz, hitNormal,
            hitMaterial);
}

void startPixel();    // the shader's: the pixel's state, and its first ray (startCameraRay)
vec3 pixelColor();    // the shader's: the finished pixel's colour

// The pixel is done: its colour is written (a NaN or infinite one is counted, so that none
// reaches the image unseen: the output encodes NaN as 0 and an infinity as 0 or 1), and the
// lane's next pixel starts: the same place in the next tile of its run, if any.
// (The column and row are stepped, not divided out: a vector's integer division is a
// division per lane on the CPU.)
void endPath() {
  vec3 color = pixelColor();
  if (any(isnan(color)) || any(isinf(color))) ++nonFinite;
  pixels[pixelY * params.width + pixelX] = vec4(color, 1.0);
  ++finished;
  do {
    ++tile;
    pixelX += kWorkgroupSize;
    if (pixelX >= params.tilesX * kWorkgroupSize) {
      pixelX -= params.tilesX * kWorkgroupSize;
      pixelY += kWorkgroupSize;
    }
  } while (tile < runEnd && (pixelX >= params.width || pixelY >= bandRows));
  if (tile < runEnd)
    startPixel();
  else
    phase = kPhaseDone;
}

// The lane's first pixel of its run, and how a suspended one goes on (its pixel is set).
void startFirstPixel() { startPixel(); }
void resumePixel() {}
