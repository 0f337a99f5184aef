#include "scene/finish_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "util/counted.h"
#include "scene/integrator_table.h"

namespace vkrt {
namespace {

bool isPerfectSquare(int n) {
  int r = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  return r * r == n;
}

// The scene's integrator as messages name it: "integrator direct (line 4)", "integrator
// raytracer (the default)".
std::string integratorNamed(const SceneDesc& scene, const Deferred& deferred) {
  return "integrator " + std::string(nameOf(scene.path.integrator)) +
         (deferred.integratorLine > 0 ? " (line " + std::to_string(deferred.integratorLine) + ")" : " (the default)");
}

// Every scene needs a `size` and a `camera`; the format puts `size` first.
void checkRequired(const Deferred& deferred, int lastLine, DiagnosticLog& log) {
  if (deferred.firstSizeLine == 0)
    log.error(1, "no 'size' command: the image size must be given ('size WIDTH HEIGHT')");
  if (deferred.cameraLine == 0) log.error(lastLine, "no 'camera' command in the scene");
  // The course's files put `size` first; its absence altogether is the error above.
  if (deferred.firstSizeLine > 0 && deferred.beforeSizeLine > 0)
    log.warn(deferred.beforeSizeLine, WarningKind::BeforeSize,
             "'" + std::string(deferred.beforeSizeCommand) + "' before 'size' (line " +
                 std::to_string(deferred.firstSizeLine) + "): accepted, though the format puts 'size' first");
}

// The settings commands that the integrator does not use (its row of integrator_table.h):
// each is ignored, with a warning at its line.
CommandSet ignoreUnusedSettings(const SceneDesc& scene, const Deferred& deferred, const std::string& which,
                                DiagnosticLog& log) {
  const Integrator integrator = scene.path.integrator;
  const CommandSet uses = integratorRow(integrator).uses;
  CommandSet ignored = 0;
  for (const auto& [cmd, line] : deferred.settings) {
    if (contains(uses, cmd)) continue;
    ignored |= commandSet({cmd});
    std::string why = cmd == Command::QuadLight && integrator == Integrator::Raytracer
                          ? " (the Whitted model has no area lights)"
                          : "";
    log.warn(line, WarningKind::NotForIntegrator,
             "'" + std::string(nameOf(cmd)) + "' ignored: " + which + " does not use it" + why);
  }
  return ignored;
}

// An ignored setting keeps the format's default, so that the scene says what is rendered.
void keepDefaults(SceneDesc& scene, CommandSet ignored) {
  const PathSettings defaults;
  const Material defaultMaterial;
  if (contains(ignored, Command::Spp)) scene.path.spp = defaults.spp;
  if (contains(ignored, Command::Gamma)) scene.path.gamma = defaults.gamma;
  if (contains(ignored, Command::LightSamples)) scene.path.lightSamples = defaults.lightSamples;
  if (contains(ignored, Command::LightStratify)) scene.path.lightStratify = defaults.lightStratify;
  if (contains(ignored, Command::NextEventEstimation)) scene.path.nextEvent = defaults.nextEvent;
  if (contains(ignored, Command::RussianRoulette)) scene.path.russianRoulette = defaults.russianRoulette;
  if (contains(ignored, Command::ImportanceSampling)) scene.path.sampling = defaults.sampling;
  for (Material& m : scene.materials) {
    if (contains(ignored, Command::Brdf)) m.brdf = defaultMaterial.brdf;
    if (contains(ignored, Command::Roughness)) m.roughness = defaultMaterial.roughness;
  }
}

// The path integrators' Phong lobe, beyond what float32 resolves (kMaxPathShininess).
void clampShininess(SceneDesc& scene, const Deferred& deferred, const std::string& which, DiagnosticLog& log) {
  for (int line : deferred.steepShininessLines)
    log.warn(line, WarningKind::Clamped,
             "shininess clamped to 1e7 for " + which +
                 " (a lobe narrower than float32 resolves: the same picture, and finite)");
  for (Material& m : scene.materials) m.shininess = std::min(m.shininess, kMaxPathShininess);
}

// `maxdepth -1` (no limit) under the integrator: an error for the Whitted model, a warning
// for the path tracer without Russian roulette.
void checkUnlimitedDepth(const SceneDesc& scene, const Deferred& deferred, const std::string& which,
                         DiagnosticLog& log) {
  if (deferred.unlimitedDepthLine == 0) return;
  // -1 (no limit) means nothing to the Whitted model: primary hit plus D reflections.
  if (scene.path.integrator == Integrator::Raytracer)
    log.error(deferred.unlimitedDepthLine,
              "'maxdepth' argument 1: expected a non-negative integer, got '-1': -1 (no limit) "
              "is for the path integrators, and " + which + " is the Whitted model");
  // -1 under the path tracer leaves Russian roulette as the only end of a path that stays in
  // the scene: without it, each such sample runs to the renderers' bounce limit.
  if (scene.path.integrator == Integrator::PathTracer && !scene.path.russianRoulette)
    log.warn(deferred.unlimitedDepthLine, WarningKind::EndlessPaths,
             "'maxdepth -1' (no limit) with 'russianroulette off': a path ends only when it leaves the scene, so in "
             "a closed scene every sample runs to the renderers' limit of tens of thousands of bounces; add "
             "'russianroulette on'");
}

// A Whitted scene with no point or directional light shows only ambient and emission. Said
// when a light would change the image: some surface has a diffuse or specular colour (the
// course's scene2 and scene3 colour theirs with ambient alone, as their authors meant). At
// the `size` line, as the scene's other whole-file diagnostics; quad lights are no light here.
void warnIfUnlit(const SceneDesc& scene, const Deferred& deferred, DiagnosticLog& log) {
  if (deferred.firstSizeLine == 0 || scene.path.integrator != Integrator::Raytracer || !scene.lights.empty() ||
      deferred.shadedSurfaceLine == 0)
    return;
  const std::string ignoredQuads =
      deferred.quadLights.empty()
          ? ""
          : " (its " + counted(deferred.quadLights.size(), "quad light is", "quad lights are") +
                " ignored: the Whitted model has no area lights; use 'point' or 'directional', or a path "
                "integrator)";
  log.warn(deferred.firstSizeLine, WarningKind::NoLights,
           "the scene has no lights: only ambient and emission light it" + ignoredQuads +
               "; the diffuse and specular colours of its surfaces (the first at line " +
               std::to_string(deferred.shadedSurfaceLine) + ") stay dark");
}

}  // namespace

// The light, its own material (emission L and nothing else), and two triangles a, a+ac,
// a+ab+ac and a, a+ab+ac, a+ab: each has face normal cross(p1 - p0, p2 - p0) along
// cross(ac, ab), the side that emits.
void addQuadLight(SceneDesc& scene, const QuadLight& q) {
  const int index = static_cast<int>(scene.quadLights.size());
  scene.quadLights.push_back(q);
  Material m;
  m.ambient = m.diffuse = m.specular = dvec3(0.0);
  m.emission = q.radiance;
  m.quadLight = index;
  scene.materials.push_back(m);
  const auto material = static_cast<std::uint32_t>(scene.materials.size() - 1);
  const dvec3 a = q.a, b = q.a + q.ab, c = q.a + q.ab + q.ac, d = q.a + q.ac;
  for (const auto& corners : {std::array<dvec3, 3>{a, d, c}, std::array<dvec3, 3>{a, c, b}}) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t.p[k] = corners[k];
    t.material = material;
    scene.triangles.push_back(t);
  }
}

void finishScene(SceneDesc& scene, const Deferred& deferred, int lastLine, DiagnosticLog& log) {
  checkRequired(deferred, lastLine, log);
  const std::string which = integratorNamed(scene, deferred);
  const CommandSet ignored = ignoreUnusedSettings(scene, deferred, which, log);
  keepDefaults(scene, ignored);
  if (scene.path.integrator != Integrator::Raytracer) clampShininess(scene, deferred, which, log);

  // `lightstratify on` cuts the light into sqrt(N) x sqrt(N) cells.
  if (deferred.lightStratifyLine > 0 && !contains(ignored, Command::LightStratify) &&
      !isPerfectSquare(scene.path.lightSamples))
    log.error(deferred.lightStratifyLine, "'lightstratify on' needs a perfect square 'lightsamples', got " +
                                              std::to_string(scene.path.lightSamples) + " (line " +
                                              std::to_string(deferred.lightSamplesLine) + ")");
  scene.path.lightSamplesLine = deferred.lightSamplesLine;
  checkUnlimitedDepth(scene, deferred, which, log);

  if (!contains(ignored, Command::QuadLight))
    for (const QuadLight& q : deferred.quadLights) addQuadLight(scene, q);
  // Unbalanced pushTransforms at the end are valid (doc/scene-format.md, "Transforms").
  warnIfUnlit(scene, deferred, log);
}

}  // namespace vkrt
