// parse -> build -> render (CPU reference or Vulkan) -> PNG, with a timer per stage.
#include "render/render.h"

#include <chrono>
#include <thread>

#include "gpu/vulkan_renderer.h"
#include "image/png.h"
#include "interrupt.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "timing.h"

namespace vkrt {
namespace {

Image renderWithCpu(const RenderRequest& request, const SceneDesc& scene, ProgressBar& progress,
                    RenderReport& report) {
  auto t0 = std::chrono::steady_clock::now();
  Bvh bvh = buildBvh(scene);
  report.buildSeconds = secondsSince(t0);
  report.bvhNodes = bvh.nodes.size();

  t0 = std::chrono::steady_clock::now();
  CpuOptions options;
  options.threads = request.threads;
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) { progress.update(done, total); };
  options.stop = [] { return pendingInterrupt() != 0; };
  report.backend = "cpu";
  report.threads = request.threads > 0 ? request.threads : static_cast<int>(std::thread::hardware_concurrency());
  Image image = renderReference(scene, bvh, options, &report.rays);
  report.renderSeconds = secondsSince(t0);
  return image;
}

Image renderWithVulkan(const RenderRequest& request, const SceneDesc& scene, ProgressBar& progress,
                       RenderReport& report) {
  auto t0 = std::chrono::steady_clock::now();
  // The device first: without one there is nothing to build for.
  Context context(ContextOptions{request.device, request.validation});
  report.instanceSeconds = context.instanceSeconds();
  report.deviceSeconds = context.deviceSeconds();
  report.backend = std::string("vulkan (") + context.properties().deviceName + ")";
  double setup = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  GpuScene gpuScene = flatten(scene);
  report.buildSeconds = secondsSince(t0);
  report.bvhNodes = gpuScene.bvh.nodes.size();

  t0 = std::chrono::steady_clock::now();
  VulkanOptions options;
  options.stepBudget = request.stepBudget;
  options.reads = request.reads;
  options.specialize = request.specialize;
  options.cutoff = request.cutoff;
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) { progress.update(done, total); };
  options.stop = [] { return pendingInterrupt() != 0; };
  Image image = renderVulkan(context, gpuScene, options, &report.rays, &report.vulkan);
  report.renderSeconds = setup + secondsSince(t0);
  return image;
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

  Image image = request.backend == Backend::Cpu ? renderWithCpu(request, scene, progress, report)
                                                : renderWithVulkan(request, scene, progress, report);
  progress.finish();
  throwIfInterrupted();   // a stopped render is incomplete: write nothing

  t0 = std::chrono::steady_clock::now();
  writePngAtomic(image, report.outputPath);
  report.writeSeconds = secondsSince(t0);
  return report;
}

}  // namespace vkrt
