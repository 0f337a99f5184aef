// parse -> build -> render (CPU reference or Vulkan) -> PNG or PPM, with a timer per stage.
#include "render/render.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "errors.h"
#include "gpu/vulkan_renderer.h"
#include "image/image_file.h"
#include "image/png.h"
#include "interrupt.h"
#include "scene/flatten.h"
#include "scene/diagnostic.h"
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
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) {
    progress.update(done, total);
    waitForSignalIfTesting("render");
  };
  options.stop = [] { return pendingInterrupt() != 0; };
  options.crop = request.crop;
  report.backend = "cpu";
  report.threads = request.threads > 0 ? request.threads : static_cast<int>(std::thread::hardware_concurrency());
  Image image = renderReference(scene, bvh, options, &report.rays);
  report.renderSeconds = secondsSince(t0);
  return image;
}

// Frees the scene's triangles and spheres once they are flattened: nothing after that reads them
// (152 bytes a triangle, 150 MB for a million, held through the upload and render otherwise).
Image renderWithVulkan(const RenderRequest& request, SceneDesc& scene, ProgressBar& progress,
                       RenderReport& report, RenderSession& session) {
  auto t0 = std::chrono::steady_clock::now();
  // The device first: without one there is nothing to build for.
  bool made = false;
  const Context& context = session.context(request, made);
  if (made) {
    report.instanceSeconds = context.instanceSeconds();
    report.deviceSeconds = context.deviceSeconds();
  }
  report.backend = std::string("vulkan (") + context.properties().deviceName + ")";
  double setup = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  GpuScene gpuScene = flatten(scene);
  report.buildSeconds = secondsSince(t0);
  report.bvhNodes = gpuScene.bvh.nodes.size();
  std::vector<Triangle>().swap(scene.triangles);
  std::vector<Sphere>().swap(scene.spheres);

  t0 = std::chrono::steady_clock::now();
  VulkanOptions options;
  options.stepBudget = request.stepBudget;
  options.reads = request.reads;
  options.specialize = request.specialize;
  options.cutoff = request.cutoff;
  options.progress = [&progress](std::uint64_t done, std::uint64_t total) {
    progress.update(done, total);
    waitForSignalIfTesting("render");
  };
  options.stop = [] { return pendingInterrupt() != 0; };
  options.crop = request.crop;
  Image image = renderVulkan(context, gpuScene, options, &report.rays, &report.vulkan);
  report.renderSeconds = setup + secondsSince(t0);
  return image;
}

// The image needs width * height * 3 bytes for as long as the render runs (the renderers and
// the PNG writer add about a megabyte to that; the Vulkan backend's bands are bounded). Refuse
// before allocating when the machine does not have that much memory available, naming the
// `size` line and both numbers, rather than dying half-way.
void checkImageFitsInMemory(const SceneDesc& scene, int width, int height) {
  const unsigned long long have = availableMemoryBytes();
  if (have == 0) return;   // unknown: let the allocation decide
  const unsigned long long need = 3ULL * static_cast<unsigned>(width) * static_cast<unsigned>(height);
  if (need > have)
    throw OutOfMemory("a " + std::to_string(width) + "x" + std::to_string(height) + " image (" +
                      scene.sourcePath + ":" + std::to_string(scene.sizeLine) + ") needs " +
                      std::to_string(need >> 20) + " MB, and this machine has " + std::to_string(have >> 20) +
                      " MB available");
}

// --strict: pixels whose colour was NaN or infinite (the scene's extreme values) are an
// error, reported before anything is written.
void checkFinite(const RenderRequest& request, const SceneDesc& scene, const RenderReport& report) {
  if (request.strict && report.rays.nonFinite > 0)
    throw SceneError({{scene.sourcePath, 0,
                       std::to_string(report.rays.nonFinite) +
                           " pixels had a NaN or infinite colour: the scene has extreme values",
                       Severity::Error}});
}

// --size and --scale: the scene's camera as it is, sampled at another resolution. A size
// beyond the parser's limit is refused as the command line's (the file is fine).
void applySizeOverride(const RenderRequest& request, SceneDesc& scene) {
  int w = scene.width, h = scene.height;
  std::string what;
  if (request.width > 0 && request.height > 0) {
    w = request.width;
    h = request.height;
    what = "--size";
  } else if (request.scale > 0) {
    auto scaled = [&](int edge) {
      double v = std::round(static_cast<double>(edge) * request.scale);
      return v < 1.0 ? 1.0 : v;
    };
    double sw = scaled(scene.width), sh = scaled(scene.height);
    if (sw > kMaxImageEdge || sh > kMaxImageEdge) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%g", request.scale);
      throw UsageError("--scale " + std::string(buf) + " makes " + scene.sourcePath + "'s " +
                       std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image " +
                       std::to_string(static_cast<long long>(sw)) + "x" + std::to_string(static_cast<long long>(sh)) +
                       ", larger than " + std::to_string(kMaxImageEdge) + " on a side");
    }
    w = static_cast<int>(sw);
    h = static_cast<int>(sh);
  }
  scene.width = w;
  scene.height = h;
}

// -o DIR/: the file name of the scene's `output` line, or the scene file's stem + ".png".
std::string pathInOutputDir(const SceneDesc& scene, const std::string& dir) {
  std::filesystem::path name = scene.outputLine > 0 ? std::filesystem::path(scene.output).filename()
                                                    : std::filesystem::path(scene.sourcePath).stem();
  if (scene.outputLine == 0) name += ".png";
  return (std::filesystem::path(dir) / name).string();
}

}  // namespace

RenderSession::RenderSession() = default;
RenderSession::~RenderSession() = default;

const Context& RenderSession::context(const RenderRequest& request, bool& made) {
  made = !context_;
  if (!context_) context_ = std::make_unique<Context>(ContextOptions{request.device, request.validation});
  return *context_;
}

unsigned long long availableMemoryBytes() {
  if (const char* test = std::getenv("VKRT_TEST_MEMORY_AVAILABLE_MB"))   // for the tests only
    return std::strtoull(test, nullptr, 10) << 20;
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  unsigned long long kb = 0;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024ULL;
  return 0;
}

std::string resolveOutput(const SceneDesc& scene, const RenderRequest& request) {
  if (request.output || request.outputDir) {
    std::string path = request.output ? *request.output : pathInOutputDir(scene, *request.outputDir);
    checkOutputWritable(path);
    return path;
  }
  try {
    checkOutputWritable(scene.output);
  } catch (const IoError& e) {
    if (scene.outputLine == 0) throw;
    throw SceneError({{scene.sourcePath, scene.outputLine, escapedBytes(e.what())}});   // the path is the file's
  }
  return scene.output;
}

Image renderSceneInMemory(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                          bool checkOutput, RenderSession* session) {
  auto t0 = std::chrono::steady_clock::now();
  ParsedScene parsed = parseSceneFileWithWarnings(request.scenePath, ParseOptions{request.strict});
  SceneDesc& scene = parsed.scene;
  report.parseSeconds = secondsSince(t0);
  if (!parsed.warnings.empty() && request.onWarnings) request.onWarnings(parsed.warnings);
  if (request.maxDepth >= 0) scene.maxDepth = request.maxDepth;
  applySizeOverride(request, scene);
  if (checkOutput) {
    report.outputPath = resolveOutput(scene, request);
    if (request.onOutput) request.onOutput(report.outputPath);
  }
  if (request.crop) {
    std::string problem = cropProblem(*request.crop, scene.width, scene.height);
    if (!problem.empty())
      throw UsageError("--crop " + formatPixelRect(*request.crop) + ": " + problem +
                       " (" + scene.sourcePath + ")");
  }
  // The image written: the whole, or the crop.
  report.width = request.crop ? request.crop->width() : scene.width;
  report.height = request.crop ? request.crop->height() : scene.height;
  checkImageFitsInMemory(scene, report.width, report.height);
  report.maxDepth = scene.maxDepth;
  report.triangles = scene.triangles.size();
  report.spheres = scene.spheres.size();
  report.lights = scene.lights.size();

  RenderSession ownSession;   // for this render only, when not lent one
  Image image = request.backend == Backend::Cpu
                    ? renderWithCpu(request, scene, progress, report)
                    : renderWithVulkan(request, scene, progress, report, session ? *session : ownSession);
  progress.finish();
  throwIfInterrupted();   // a stopped render is incomplete: write nothing
  checkFinite(request, scene, report);
  if (request.crop) image.text.emplace_back(kCropKeyword, formatCropRecord({*request.crop, scene.width, scene.height}));
  return image;
}

RenderReport renderSceneFile(const RenderRequest& request, ProgressBar& progress, Image* image,
                             RenderSession* session) {
  RenderReport report;
  Image rendered = renderSceneInMemory(request, progress, report, true, session);
  auto t0 = std::chrono::steady_clock::now();
  writeImageAtomic(rendered, report.outputPath);
  report.writeSeconds = secondsSince(t0);
  if (image) *image = std::move(rendered);
  return report;
}

}  // namespace vkrt
