// parse -> flatten -> render -> PNG, with a timer per stage.
#include "render/render.h"

#include <chrono>
#include <thread>

#include "image/png.h"
#include "scene/flatten.h"
#include "scene/parse.h"

namespace vkrt {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::string resolveOutput(const SceneDesc& scene, const std::optional<std::string>& override) {
  if (override) {
    checkOutputWritable(*override);
    return *override;
  }
  try {
    checkOutputWritable(scene.output);
  } catch (const IoError& e) {
    if (scene.outputLine == 0) throw;
    throw SceneError({{scene.sourcePath, scene.outputLine, e.what()}});
  }
  return scene.output;
}

RenderReport renderSceneFile(const RenderRequest& request, ProgressBar& progress) {
  RenderReport report;
  auto t0 = std::chrono::steady_clock::now();
  SceneDesc scene = parseSceneFile(request.scenePath);
  report.parseSeconds = secondsSince(t0);
  report.outputPath = resolveOutput(scene, request.output);
  report.width = scene.width;
  report.height = scene.height;
  report.maxDepth = scene.maxDepth;
  report.triangles = scene.triangles.size();
  report.spheres = scene.spheres.size();
  report.lights = scene.lights.size();

  t0 = std::chrono::steady_clock::now();
  Bvh bvh = buildBvh(scene);
  report.buildSeconds = secondsSince(t0);
  report.bvhNodes = bvh.nodes.size();

  t0 = std::chrono::steady_clock::now();
  CpuOptions options;
  options.threads = request.threads;
  report.threads = request.threads > 0 ? request.threads : static_cast<int>(std::thread::hardware_concurrency());
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) { progress.update(done, total); };
  Image image = renderReference(scene, bvh, options, &report.rays);
  progress.finish();
  report.renderSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  writePngAtomic(image, report.outputPath);
  report.writeSeconds = secondsSince(t0);
  return report;
}

}  // namespace vkrt
