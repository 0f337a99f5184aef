// parse -> build -> render (CPU reference or Vulkan, in sample batches) -> PNG, PPM or PFM,
// with a timer per stage.
#include "util/ray_counts.h"
#include "render/render.h"

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "util/counted.h"
#include "util/errors.h"
#include "gpu_types.h"
#include "gpu/context.h"
#include "image/atomic_file.h"
#include "image/encode.h"
#include "image/image_file.h"
#include "image/render_identity.h"
#include "image/row_sink.h"
#include "image/samples.h"
#include "util/interrupt.h"
#include "platform/path_text.h"
#include "platform/process.h"
#include "render/backend.h"
#include "render/progressive.h"
#include "render/techniques.h"
#include "scene/emitters.h"
#include "scene/flatten.h"
#include "scene/diagnostic.h"
#include "scene/parse.h"
#include "scene/shapes/shape.h"
#include "util/timing.h"

namespace vkrt {

static_assert(kMaxRecordedImageEdge == kMaxImageEdge, "merge's record limit (image/crop.h) is the render's");

namespace {

// The sample count a render without --spp limit (--time alone) is planned as.
constexpr int kMaxSamplesPerPixel = 1 << 30;

// Renders the plan's samples in batches (render/progressive) and reports them. (Only the
// Whitted model streams its rows: it is one batch; a progressive mean is held whole.)
RadianceImage renderBatches(const BatchRenderer& batches, const SamplePlan& plan, RenderReport& report) {
  ProgressiveReport done;
  RadianceImage image = renderProgressive(batches, plan.progressive, &done);
  report.samples = done.samples;
  report.batches = done.batches;
  report.timeUp = done.timeUp;
  report.firstBatchPastLimit = done.firstBatchPastLimit;
  return image;
}

// Warns (or with --strict refuses) an option that the scene's integrator ignores.
void warnOption(const RenderRequest& request, const std::string& warning) {
  if (request.strict) throw UsageError(warning + " [--strict]");
  if (request.onOptionWarning) request.onOptionWarning(warning);
}

// --estimator best on a `pathtracer` scene: BRDF sampling, and next-event estimation combined
// with the scattered rays' hits by MIS (doc/path-tracing.md, "Estimators": the same image in
// the limit). Returns the path tracer's estimator as rendered ("" for other integrators).
std::string applyEstimator(const RenderRequest& request, SceneDesc& scene) {
  PathSettings& path = scene.path;
  if (path.integrator != Integrator::PathTracer) {
    if (request.estimator == Estimator::Best)
      warnOption(request, "--estimator best does not apply to " + scene.sourcePath + ": its integrator is " +
                              std::string(nameOf(path.integrator)) + ", not pathtracer");
    return "";
  }
  if (request.estimator == Estimator::Best) {
    path.sampling = Sampling::Brdf;
    path.nextEvent = NextEvent::Mis;
  }
  return "nexteventestimation " + std::string(kNextEventNames[static_cast<int>(path.nextEvent)]) +
         ", importancesampling " + std::string(kSamplingNames[static_cast<int>(path.sampling)]) +
         ", russianroulette " + (path.russianRoulette ? "on" : "off") +
         (request.stratified ? ", stratified samples" : ", independent samples") +
         (request.estimator == Estimator::Best ? " (--estimator best)" : "");
}

// The samples of this render, and the warnings for options that do not apply (the Whitted
// model and the views have one deterministic sample: --spp, --seed, --time and --sampler
// change nothing).
SamplePlan samplePlan(const RenderRequest& request, const SceneDesc& scene, bool sampled, ProgressBar& progress) {
  SamplePlan plan;
  plan.progressive.stop = [] { return pendingInterrupt() != 0; };
  if (!sampled) {
    std::vector<std::string> given;
    if (request.spp > 0) given.push_back("--spp");
    if (request.seed) given.push_back("--seed");
    if (request.timeLimitSeconds > 0) given.push_back("--time");
    if (request.stratified) given.push_back("--sampler stratified");
    if (!given.empty()) {
      std::string list;
      for (std::size_t i = 0; i < given.size(); ++i)
        list += (i == 0 ? "" : i + 1 == given.size() ? " and " : ", ") + given[i];
      warnOption(request, list + (given.size() > 1 ? " do" : " does") + " not apply to " +
                              (request.view.empty() ? scene.sourcePath + ": its integrator is raytracer"
                                                    : "--view " + request.view) +
                              " (one deterministic sample per pixel)");
    }
    plan.progressive.spp = 1;   // one batch; the bar counts pixels (the backend's progress)
    plan.progressive.progress = nullptr;
    return plan;
  }
  plan.seed = request.seed.value_or(0);
  plan.progressive.spp = request.spp > 0 ? request.spp
                         : request.timeLimitSeconds > 0 ? 0
                                                        : static_cast<std::uint64_t>(scene.path.spp);
  plan.progressive.timeLimitSeconds = request.timeLimitSeconds;
  if (request.onImageRows) plan.progressive.onBatch = [&request](const RadianceImage& mean) { request.onImageRows(0, mean); };
  if (request.timeLimitSeconds <= 0 && !request.onImageRows)   // a viewer sees batches grow from one sample
    plan.progressive.firstBatchSamples =
        static_cast<std::uint32_t>(std::min<std::uint64_t>(plan.progressive.spp, plan.progressive.maxBatchSamples));
  plan.progressive.progress = &progress;
  return plan;
}

// The memory a streamed render needs besides the scene (the Whitted model, written to a
// file). Vulkan: the suspended states (VulkanOptions::maxStateBytes, 64 MB), and the band's
// pixels and their float copy (28 bytes a pixel of a band sized to those states: about 55 MB
// on lavapipe, less on a GPU; at least 8 rows, 224 bytes a column). CPU: a band of about a
// million pixels (12 MB; at least 16 rows, 192 bytes a column). Both: the encoder's rows and
// zlib's megabyte. 128 MB and 1 KB a column cover either.
unsigned long long streamedRenderBytes(int width) {
  return (128ULL << 20) + 64ULL * static_cast<unsigned>(width) * 16;
}

// A render held whole needs width * height * 15 bytes for as long as the render runs: 12 for
// the linear float image the renderers return, 3 for the bytes it is encoded into for PPM or
// --check (a progressive render's running mean is that float image, each batch one more). A
// streamed one needs streamedRenderBytes, whatever its height. Refuse before allocating when
// the machine does not have that much memory available, naming the `size` line and both
// numbers, rather than dying half-way.
void checkImageFitsInMemory(const SceneDesc& scene, int width, int height, bool streamed) {
  const unsigned long long have = availableMemoryBytes();
  if (have == 0) return;   // unknown: let the allocation decide
  const unsigned long long need = streamed ? streamedRenderBytes(width)
                                           : 15ULL * static_cast<unsigned>(width) * static_cast<unsigned>(height);
  if (need > have)
    throw OutOfMemory("a " + std::to_string(width) + "x" + std::to_string(height) + " image (" +
                      scene.sourcePath + ":" + std::to_string(scene.sizeLine) + ") needs " +
                      std::to_string(need >> 20) + " MB" + (streamed ? " (streamed in bands)" : "") +
                      ", and this machine has " + std::to_string(have >> 20) + " MB available");
}

// The render's identity (image/render_identity.h): the scene file's bytes and every setting
// that changes the picture: the full image size (after --size or --scale), maxdepth (after
// --maxdepth), the view (--view) and, for a path integrator, whether its camera samples pixel
// centres (spp 1: gpu_types.h; --spp and --time decide). Left out: the crop (tiles of one render differ in
// it), the seed and the samples (batches of one render differ in them; the samples record
// keeps them apart), and what changes only rounding or speed (the backend and device,
// threads, --reads, --step-budget, --no-specialize, --cutoff).
std::uint64_t renderIdentity(const SceneDesc& scene, bool pathIntegrator, const std::string& view) {
  Fnv1a64 hash;
  hash.add("vkrt-render 1\nsize " + std::to_string(scene.width) + " " + std::to_string(scene.height) +
           "\nmaxdepth " + std::to_string(scene.maxDepth) + "\n");
  if (!view.empty()) hash.add("view " + view + "\n");   // (none: the identities of before views)
  if (pathIntegrator) hash.add(std::string("pixel-centres ") + (scene.path.spp == 1 ? "1" : "0") + "\n");
  // The scene's text as it was parsed (hashed by the parser: the file is not read again, and a
  // scene read from a pipe has its identity too).
  hash.add("scene " + formatRenderIdentity(scene.sourceHash) + "\n");
  return hash.value();
}

// What a file receives is finite: a NaN channel (counted, and warned of) becomes 0 and an
// infinite one the largest float of its sign, as the 8-bit encoding reads them.
void keepFinite(RadianceImage& image) {
  constexpr float kMax = std::numeric_limits<float>::max();
  for (float& c : image.rgb)
    if (!std::isfinite(c)) c = std::isnan(c) ? 0.0f : std::copysign(kMax, c);
}

// A streamed band as the file receives it: itself, or a finite copy when it has a NaN or an
// infinity (rare: the copy is made only then).
const RadianceImage& finiteBand(const RadianceImage& band, RadianceImage& copy) {
  if (std::all_of(band.rgb.begin(), band.rgb.end(), [](float c) { return std::isfinite(c); })) return band;
  copy = band;
  keepFinite(copy);
  return copy;
}

// --strict: pixels whose colour was NaN or infinite (the scene's extreme values) are an
// error, reported before anything is written.
void checkFinite(const RenderRequest& request, const SceneDesc& scene, const RenderReport& report) {
  if (request.strict && report.rays.nonFinite > 0)
    throw SceneError({{scene.sourcePath, 0,
                       counted(report.rays.nonFinite, "pixel", "pixels") +
                           " had a NaN or infinite colour: the scene has extreme values",
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

// -o DIR/: the file name of the scene's `output` line, or the scene file's stem + the default
// format's extension.
std::string pathInOutputDir(const SceneDesc& scene, const std::string& dir) {
  if (scene.outputLine == 0) return defaultOutputIn(dir, scene.sourcePath);
  return platform::utf8FromPath(platform::pathFromUtf8(dir) / platform::pathFromUtf8(scene.output).filename());
}

}  // namespace

std::string defaultOutputIn(const std::string& dir, const std::string& scenePath) {
  using platform::pathFromUtf8;
  return platform::utf8FromPath(pathFromUtf8(dir) / pathFromUtf8(scenePath).stem().concat(defaultImageExtension()));
}

RenderSession::RenderSession() = default;
RenderSession::~RenderSession() = default;

void RenderSession::prepare(const RenderRequest& request) {
  if (context_ || pending_.valid()) return;
  ContextOptions options{request.device, request.validation};
  pending_ = std::async(std::launch::async, [options] { return std::make_unique<Context>(options); });
}

const Context& RenderSession::context(const RenderRequest& request, bool& made) {
  made = !context_;
  if (context_) return *context_;
  if (pending_.valid()) {
    context_ = pending_.get();   // rethrows its DeviceError
  } else {
    context_ = std::make_unique<Context>(ContextOptions{request.device, request.validation});
  }
  return *context_;
}

unsigned long long availableMemoryBytes() {
  if (const char* test = std::getenv("VKRT_TEST_MEMORY_AVAILABLE_MB"))   // for the tests only
    return std::strtoull(test, nullptr, 10) << 20;
  return platform::availableMemoryBytes();
}

std::string resolveOutput(const SceneDesc& scene, const RenderRequest& request) {
  if (request.output || request.outputDir) {
    std::string path = request.output ? *request.output : pathInOutputDir(scene, *request.outputDir);
    if (request.onOutput) request.onOutput(path);
    checkOutputWritable(path);
    return path;
  }
  try {
    if (request.onOutput) request.onOutput(scene.output);
    checkOutputWritable(scene.output);
  } catch (const IoError& e) {
    if (scene.outputLine == 0) throw;
    throw SceneError({{scene.sourcePath, scene.outputLine, escapedBytes(e.what())}});   // the path is the file's
  }
  return scene.output;
}

namespace {

// The lights of RenderReport::Lights. The Whitted model's are the point and directional
// lights alone (the parser drops its quad lights); an emissive surface lights other surfaces
// only under the path tracer (found by its paths, and sampled by next-event estimation).
RenderReport::Lights countLights(const SceneDesc& scene) {
  RenderReport::Lights n;
  for (const Light& l : scene.lights) ++n.byType[static_cast<std::size_t>(l.type)];
  n.quad = scene.quadLights.size();
  if (scene.path.integrator == Integrator::PathTracer)
    for (std::uint32_t prim : collectEmitters(scene).prims)
      ++n.emissive[gpu::primKind(prim)];
  return n;
}

// A render once its scene is parsed and its settings checked.
struct PreparedRender {
  ParsedScene parsed;
  SamplePlan plan;
  bool streamed = false;                  // the rows go to the file as they are rendered
  std::optional<std::uint64_t> identity;  // for the records of a crop or a path integrator's image
  std::optional<std::chrono::steady_clock::time_point> deadline;   // RenderLimits::seconds after parsing began
};

// Whether the render has run past its time limit.
bool pastDeadline(const PreparedRender& prepared) {
  return prepared.deadline && std::chrono::steady_clock::now() >= *prepared.deadline;
}

// Parses the scene, applies the overrides, resolves the output (when `checkOutput`), checks
// the crop and the memory, fills the report's facts of the scene, and plans the samples. The
// render streams when `mayStream` and the scene is the Whitted model's (one batch).
void prepareRender(const RenderRequest& request, ProgressBar& progress, RenderReport& report, bool checkOutput,
                   bool mayStream, RenderSession& vulkan, PreparedRender& prepared) {
  if (request.backend == Backend::Vulkan && !request.dryRun) vulkan.prepare(request);
  auto t0 = std::chrono::steady_clock::now();
  if (request.limits.seconds > 0)
    prepared.deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(request.limits.seconds));
  prepared.parsed = parseSceneFileWithWarnings(request.scenePath, ParseOptions{request.strict, request.output.has_value(), outputNameProblem});
  SceneDesc& scene = prepared.parsed.scene;
  report.parseSeconds = secondsSince(t0);
  if (pastDeadline(prepared)) throw timeLimitExceeded(request.limits, scene);
  if (!prepared.parsed.warnings.empty() && request.onWarnings) request.onWarnings(prepared.parsed.warnings);
  if (request.maxDepth >= 0) scene.maxDepth = request.maxDepth;
  applySizeOverride(request, scene);
  report.estimator = applyEstimator(request, scene);
  // The backend's own limits (the Vulkan shader's random numbers): said at the scene's line,
  // not the device's, and before anything is rendered (also by --dry-run).
  validateForBackend(request, scene);
  if (checkOutput) {
    report.outputPath = resolveOutput(scene, request);
  }
  if (request.crop) {
    std::string problem = cropProblem(*request.crop, scene.width, scene.height);
    if (!problem.empty())
      throw UsageError("--crop " + formatPixelRect(*request.crop) + ": " + problem +
                       " (" + scene.sourcePath + ")");
  }
  report.pathIntegrator = techniqueFor(scene, request.view).sampled;
  prepared.streamed = mayStream && !report.pathIntegrator;
  // The image written: the whole, or the crop.
  report.width = request.crop ? request.crop->width() : scene.width;
  report.height = request.crop ? request.crop->height() : scene.height;
  report.maxDepth = scene.maxDepth;
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind) report.primitives[kind] = shapes::count(scene, kind);
  report.lights = countLights(scene);

  // The Whitted model ignores `gamma` (doc/path-tracing.md, "Commands"): its bytes are doc/scene-format.md
  // section 7's, and the shader's exactness cut-off reasons in those (gamma 1); a view's are its
  // values, linear.
  report.gamma = report.pathIntegrator ? scene.path.gamma : 1.0;
  prepared.plan = samplePlan(request, scene, report.pathIntegrator, progress);
  const SamplePlan& plan = prepared.plan;
  checkRenderLimits(request.limits, scene, report.pathIntegrator, plan.progressive.spp);
  checkImageFitsInMemory(scene, report.width, report.height, prepared.streamed);
  if (prepared.deadline)
    prepared.plan.progressive.stop = [deadline = *prepared.deadline] {
      return pendingInterrupt() != 0 || std::chrono::steady_clock::now() >= deadline;
    };
  // The render's total decides the camera rule (gpu_types.h: spp 1 samples pixel centres):
  // --spp N renders as a scene of spp N, and --time alone as one of unbounded spp.
  if (report.pathIntegrator)
    scene.path.spp = plan.progressive.spp > 0 && plan.progressive.spp < kMaxSamplesPerPixel
                         ? static_cast<int>(plan.progressive.spp)
                         : kMaxSamplesPerPixel;
  if (request.crop || report.pathIntegrator) prepared.identity = renderIdentity(scene, report.pathIntegrator, request.view);
}

// Renders a prepared scene; with `rows`, each band goes there as it is finished (the image
// returned then has no pixels). Nothing may be written after a stop or a --strict failure.
RadianceImage renderPrepared(const RenderRequest& request, PreparedRender& prepared, ProgressBar& progress,
                             RenderReport& report, RenderSession& vulkan, const RowSink* rows) {
  SceneDesc& scene = prepared.parsed.scene;
  std::unique_ptr<RenderBackend> backend = makeBackend(request, progress, report, vulkan, prepared.plan, rows);
  backend->build(scene);
  auto t0 = std::chrono::steady_clock::now();
  RadianceImage image = renderBatches(
      [&](const SampleBatch& batch, const PixelProgress& px) { return backend->renderBatch(batch, px); },
      prepared.plan, report);
  report.renderSeconds += secondsSince(t0);
  backend->finish();
  backend.reset();   // (the BVH, the GPU's arrays and buffers: nothing after this reads them)
  progress.finish();
  throwIfInterrupted();   // a stopped render is incomplete: write nothing
  if (pastDeadline(prepared)) throw timeLimitExceeded(request.limits, scene);
  checkFinite(request, scene, report);
  keepFinite(image);
  return image;
}

// The records the image carries: a crop's place; a path integrator's samples (so that
// batches rendered apart, with other seeds, can be averaged by `vkrt merge`; the Whitted
// model's image is exact: none); and with either, the render's identity, so that merge can
// tell the parts of one render from those of another.
std::vector<std::pair<std::string, std::string>> imageRecords(const RenderRequest& request,
                                                              const PreparedRender& prepared,
                                                              const RenderReport& report) {
  const SceneDesc& scene = prepared.parsed.scene;
  std::vector<std::pair<std::string, std::string>> text;
  if (request.crop) text.emplace_back(kCropKeyword, formatCropRecord({*request.crop, scene.width, scene.height}));
  if (report.pathIntegrator)
    text.emplace_back(kSamplesKeyword,
                      formatSampleRecord({{{prepared.plan.seed, prepared.plan.progressive.firstSample, report.samples}},
                                          scene.path.gamma,
                                          request.stratified}));
  if (prepared.identity) text.emplace_back(kRenderKeyword, formatRenderIdentity(*prepared.identity));
  return text;
}

}  // namespace

RadianceImage renderSceneInMemory(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                                  bool checkOutput, RenderSession* session) {
  RenderSession ownSession;   // for this render only, when not lent one
  RenderSession& vulkan = session ? *session : ownSession;
  PreparedRender prepared;
  prepareRender(request, progress, report, checkOutput, false, vulkan, prepared);
  if (request.onImageStart) request.onImageStart(report);
  // A viewer of a Whitted render (--watch, vkrt view) sees its bands as they finish: the render
  // streams them through here into the image held. (Batches: onBatch has each mean.)
  RadianceImage held;
  RowSink bands;
  if (request.onImageRows && !report.pathIntegrator) {
    held = RadianceImage(report.width, report.height);
    bands = [&held, &request](int y0, const RadianceImage& band) {
      std::copy(band.rgb.begin(), band.rgb.end(), held.rgb.begin() + static_cast<std::ptrdiff_t>(y0) * held.width * 3);
      request.onImageRows(y0, band);
    };
  }
  RadianceImage image = renderPrepared(request, prepared, progress, report, vulkan, bands ? &bands : nullptr);
  if (bands) {
    keepFinite(held);
    image = std::move(held);
    request.onImageRows(0, image);   // whole, at the end
  }
  image.text = imageRecords(request, prepared, report);
  return image;
}

RenderReport renderSceneFile(const RenderRequest& request, ProgressBar& progress, Image* image,
                             RenderSession* session, RadianceImage* radiance) {
  RenderReport report;
  RenderSession ownSession;
  RenderSession& vulkan = session ? *session : ownSession;
  PreparedRender prepared;
  prepareRender(request, progress, report, true, image == nullptr, vulkan, prepared);
  if (request.dryRun) return report;
  if (request.onImageStart) request.onImageStart(report);
  if (!prepared.streamed) {
    RadianceImage rendered = renderPrepared(request, prepared, progress, report, vulkan, nullptr);
    if (request.onImageRows && !report.pathIntegrator) request.onImageRows(0, rendered);   // (batches: onBatch had it)
    rendered.text = imageRecords(request, prepared, report);
    auto t0 = std::chrono::steady_clock::now();
    writeImageAtomic(rendered, report.outputPath, report.gamma);
    report.writeSeconds = secondsSince(t0);
    if (image) *image = encodeImage(rendered, report.gamma);
    if (image && radiance) *radiance = std::move(rendered);
    return report;
  }
  // Streamed: the file is open while the render runs, and each band is encoded as it comes;
  // the time spent encoding is the write's, not the render's.
  double encodeSeconds = 0;
  writeImageStreamed(report.outputPath, report.gamma, report.width, report.height,
                     imageRecords(request, prepared, report), [&](const RowSink& sink) {
                       RowSink timed = [&](int y0, const RadianceImage& band) {
                         if (request.onImageRows) request.onImageRows(y0, band);
                         auto t0 = std::chrono::steady_clock::now();
                         RadianceImage copy;
                         sink(y0, finiteBand(band, copy));
                         encodeSeconds += secondsSince(t0);
                       };
                       renderPrepared(request, prepared, progress, report, vulkan, &timed);
                     });
  report.renderSeconds = std::max(0.0, report.renderSeconds - encodeSeconds);
  report.writeSeconds = encodeSeconds;
  return report;
}

}  // namespace vkrt
