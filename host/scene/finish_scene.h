// What happens after the last command: what only the whole file can say is checked (a `size`
// and a `camera`; the integrator's settings, the integrator being known only now), the
// settings the integrator does not use keep their defaults, the path integrators' Phong lobes
// are clamped, and quad lights become geometry (doc/path-tracing.md, "Commands" and "Warnings
// and errors"; doc/scene-format.md, "Warnings").
#pragma once

#include <string_view>
#include <vector>

#include "scene/commands.h"
#include "scene/diagnostic_log.h"
#include "scene/scene_desc.h"

namespace vkrt {

// A Phong exponent above this is clamped to it for the path integrators: a lobe narrower
// than float32 resolves (cos near 1 in float steps by 6e-8, about 3.5e-4 rad), which the
// Vulkan backend drew too dark (a quarter at 3e8; measured: the two backends agree to
// 1/255 at 3e7 with BRDF sampling, and 5/255 apart at 1e8) (doc/robustness.md, "Numerical
// robustness").
inline constexpr double kMaxPathShininess = 1e7;

// A settings command (integrator_table.h) and its line.
struct SettingLine {
  Command command;
  int line;
};

// What the commands leave for the end of file: the lines of what is checked only there
// (0: no such line), and what waits for the integrator.
struct Deferred {
  int firstSizeLine = 0;                 // the first `size`
  int cameraLine = 0;                    // the last `camera`
  int beforeSizeLine = 0;                // the first command before `size`...
  std::string_view beforeSizeCommand;    // ...and its name
  int shadedSurfaceLine = 0;             // the first object with a diffuse or specular colour
  int integratorLine = 0;                // the last `integrator`
  int lightSamplesLine = 0;              // the last `lightsamples`
  int lightStratifyLine = 0;             // of the last `lightstratify`, when it said `on`
  int unlimitedDepthLine = 0;            // of the last `maxdepth`, when it said -1
  std::vector<int> steepShininessLines;  // `shininess` lines above kMaxPathShininess
  std::vector<SettingLine> settings;     // every settings command, in file order
  std::vector<QuadLight> quadLights;     // geometry once the integrator is known to use them
};

// `quadLight a ab ac L` as geometry: the light, its own material (emission L and nothing
// else) and two triangles facing cross(ac, ab), the side that emits. Tests build their quad
// lights with it too, so that they are the parser's.
void addQuadLight(SceneDesc& scene, const QuadLight& q);

// Ends `scene`, whose file's last line is `lastLine` (1 for an empty file), with what the
// commands left in `deferred`; the diagnostics go to `log`.
void finishScene(SceneDesc& scene, const Deferred& deferred, int lastLine, DiagnosticLog& log);

}  // namespace vkrt
