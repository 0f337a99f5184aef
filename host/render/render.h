// The whole pipeline for one scene file: parse -> build (BVH, GPU layouts) -> render with a
// backend, in sample batches (render/progressive.h) -> RadianceImage -> PNG, PPM or PFM. Knows nothing of the command line; main() turns its exceptions into exit codes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/vulkan_settings.h"
#include "scene/light.h"
#include "image/crop.h"
#include "image/image.h"
#include "image/radiance_image.h"
#include "render/progress.h"
#include "render/render_limits.h"
#include "util/ray_counts.h"
#include "scene/diagnostic.h"
#include "scene/scene_desc.h"
#include "scene/shapes/shape.h"

namespace vkrt {

class Context;   // gpu/context.h: made and used in render.cpp only

enum class Backend { Vulkan, Cpu };

// The path tracer's estimator (RenderRequest::estimator).
enum class Estimator { Scene, Best };

struct RenderReport;

struct RenderRequest {
  std::string scenePath;
  std::optional<std::string> output;   // overrides the scene's `output`
  // A folder for the image instead (-o DIR/): DIR/ + the file name of the scene's `output`,
  // or DIR/ + the scene file's stem + ".png" when the scene has no `output` line.
  std::optional<std::string> outputDir;
  // The image size instead of the scene's `size` (the camera's fovy kept, the pixel centres
  // of doc/scene-format.md, "Camera" for the new size): width and height when both > 0 (--size WxH), else
  // the scene's size times `scale` when > 0 (--scale F), rounded, at least 1x1.
  int width = 0, height = 0;
  double scale = 0;
  // Only these pixels of the full image (the size above), as an image of the crop's size
  // carrying its CropRecord (Image::text): the pixels of a full render, bit for bit.
  std::optional<PixelRect> crop;
  Backend backend = Backend::Vulkan;
  int threads = 0;                     // CPU backend: 0 = every hardware thread
  std::string device;                  // Vulkan: "" (choose), an index or part of a name
  bool validation = false;             // Vulkan: enable the validation layer
  std::uint32_t stepBudget = 0;        // Vulkan: steps per pixel per dispatch (0: default)
  SceneReads reads = SceneReads::Auto; // Vulkan: how the shader reads the scene
  ShaderVariant variant = ShaderVariant::Auto;    // Vulkan: the shader variant (gpu/shader_variant.h)
  Cutoff cutoff = Cutoff::Auto;        // Vulkan: the exactness cut-off of the mirror loop
  bool wideBvh = false;                // Vulkan: a BVH of four children a node (--bvh wide; VulkanOptions)
  int maxDepth = -1;                   // overrides the scene's `maxdepth` when >= 0
  // A view of the scene instead of its image (--view NAME: render/techniques.h, viewNamed), or
  // "": the scene's own technique.
  std::string view;
  // --dry-run: renderSceneFile parses the scene, applies the overrides and checks what a render
  // checks first (the output path and its file, the crop, the memory), fills the report's
  // facts of the scene (output, size, primitives, lights), and returns: no device is opened,
  // nothing is rendered or written.
  bool dryRun = false;
  // Path integrators (SceneDesc::path.integrator other than Raytracer): the samples per pixel
  // instead of the scene's `spp` when > 0 (--spp); the random generator's seed (--seed); a
  // time limit in seconds when > 0 (--time): batches of samples until it is up, then the
  // image; with no spp given, the time alone decides (the scene's `spp` is then no limit).
  // The Whitted model (one deterministic sample) ignores them, with a warning
  // (onOptionWarning) when given.
  std::uint64_t spp = 0;
  std::optional<std::uint32_t> seed;   // none: 0
  double timeLimitSeconds = 0;
  // Path integrators: stratified samples (--sampler stratified; gpu_rng.h, rngStratify)
  // instead of independent ones. The Whitted model ignores it.
  bool stratified = false;
  // The path tracer's estimator (--estimator): the scene's own (`importancesampling`,
  // `nexteventestimation`), or one for the same image that is usually less noisy
  // (Estimator::Best: BRDF sampling, and light and BRDF samples combined by MIS). Other integrators ignore it, with a
  // warning (onOptionWarning).
  Estimator estimator = Estimator::Scene;
  // Every warning is an error: the scene's (doc/scene-format.md, "Warnings and errors"), and pixels whose colour came
  // out NaN or infinite (then no image is written).
  bool strict = false;
  // Bounds on the render's work (render/render_limits.h: `vkrt grade`'s, for the students'
  // scene files): past one, LimitExceeded, and nothing written. None by default.
  RenderLimits limits;
  // Called with the output path once it is resolved, before it is checked for writing (so
  // that a file the run reads is refused as such, whatever else is wrong with replacing it)
  // and before the render starts; it may throw to refuse the path (a batch refuses a path an
  // earlier scene wrote).
  std::function<void(const std::string&)> onOutput;
  // Called once with the scene's warnings, if it has any, after parsing and before the
  // render starts (not called with --strict: they are errors then).
  std::function<void(const std::vector<Diagnostic>&)> onWarnings;
  // Called with a warning about the command line that only the parsed scene reveals (--spp
  // for a Whitted scene), before the render starts. With `strict` such a warning is a
  // UsageError instead.
  std::function<void(const std::string&)> onOptionWarning;
  // For a viewer of the render as it refines (--display-server, vkrt view): the report once the
  // scene's facts are in (its output path, size, gamma, integrator), before the render starts;
  // then the image's linear rows as they are finished: each band of a Whitted render (also one
  // held in memory), the running mean after each batch of a sampled one (y0 0: the batches
  // then grow from one sample, as under --time), and the whole image at the end. Both must
  // return soon: the render waits for them.
  std::function<void(const RenderReport& report)> onImageStart;
  std::function<void(int y0, const RadianceImage& rows)> onImageRows;
};

struct RenderReport {
  std::string outputPath;
  std::string backend;                 // "cpu" or "vulkan (DEVICE NAME)"
  int width = 0, height = 0, maxDepth = 0, threads = 0;
  std::array<std::size_t, shapes::kKinds> primitives{};   // by kind of shape (scene/shapes/shape.h: kNames)
  std::size_t bvhNodes = 0;
  // The lights the integrator uses: point and directional lights, by type (scene/light.h:
  // kLightTypeNames); quad lights (the path integrators'; the Whitted model ignores them);
  // and for `pathtracer` the emissive primitives by kind of shape, which light the scene
  // there too (scene/emitters.h).
  struct Lights {
    std::array<std::size_t, kLightTypeCount> byType{};
    std::size_t quad = 0;
    std::array<std::size_t, shapes::kKinds> emissive{};
    std::size_t total() const {
      std::size_t n = quad;
      for (std::size_t k : byType) n += k;
      for (std::size_t k : emissive) n += k;
      return n;
    }
  } lights;
  double parseSeconds = 0, buildSeconds = 0, renderSeconds = 0, writeSeconds = 0;
  // Vulkan only: context creation, then the renderer's own breakdown (parts of renderSeconds).
  double instanceSeconds = 0, deviceSeconds = 0;
  // Vulkan only: the first batch's pipeline made while the BVH built (part of buildSeconds),
  // and the pipelines the render made in all (1 when the batches took that one, 0 when the
  // context held it already).
  double pipelineAheadSeconds = 0;
  std::size_t pipelinesMade = 0;
  VulkanTimings vulkan;
  RayCounts rays;
  // The samples per pixel rendered, in how many batches; whether a time limit ended the render
  // before its spp; the gamma the image is encoded with at output (the scene's `gamma`).
  bool pathIntegrator = false;   // batches of random samples (Technique::sampled); false: the Whitted model or a view (one deterministic sample)
  std::uint64_t samples = 1;
  std::uint32_t batches = 1;
  bool timeUp = false;
  double firstBatchPastLimit = 0;   // ProgressiveReport's: --time shorter than the first batch
  double gamma = 1.0;
  // The path tracer's estimator as rendered: "nexteventestimation mis, importancesampling
  // brdf, ..." (empty for the other integrators).
  std::string estimator;
};

// What scenes rendered one after another in one process share: the Vulkan context (instance
// and logical device), made at the first Vulkan render and kept for the next. One session
// serves one device choice (the first request's `device` and `validation`).
class RenderSession {
 public:
  RenderSession();
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;
  // Starts making the context on another thread (when there is none yet), so that loading
  // the driver and creating the instance and device overlap parsing the scene and building
  // its BVH. A failure is kept for context() to throw, so that a scene's own errors come first.
  void prepare(const RenderRequest& request);
  // The context: the one prepare() started (waited for), or made now on the first call
  // (throws DeviceError); `made` says whether this render made it (its instance and device
  // times are then this render's).
  const Context& context(const RenderRequest& request, bool& made);

 private:
  std::unique_ptr<Context> context_;
  std::future<std::unique_ptr<Context>> pending_;   // prepare()'s, until context() takes it
};

// Throws SceneError (bad scene, including an unwritable `output`), IoError (files),
// DeviceError (Vulkan), OutOfMemory (also before allocating an image larger than the memory
// available), UsageError (a --size or --scale beyond the largest image, a crop not inside the
// image), InternalError,
// Interrupted. The image is written as its name says (image/image_file.h: .pfm as PFM, .ppm
// as PPM, else PNG). A Whitted render is streamed: each band of rows is encoded into the
// temporary file as the renderer finishes it (image/row_sink.h), so memory does not grow with
// the image; a path integrator's (its running mean) is held whole. `image`, when given,
// receives the rendered image (for --check; the render is then held whole too), and
// `radiance`, when given with it, the linear image before encoding (--check against a float
// reference: HDR-FLIP). `session`, when given, lends the Vulkan context of earlier renders
// (without: one is made and destroyed).
RenderReport renderSceneFile(const RenderRequest& request, ProgressBar& progress, Image* image = nullptr,
                             RenderSession* session = nullptr, RadianceImage* radiance = nullptr);

// The same without writing the image (--compare): the linear image, with its records (the
// crop's, and a path integrator's vkrt-samples: image/samples.h); report.gamma encodes it.
// `checkOutput` also resolves and checks the output path first, as renderSceneFile does.
RadianceImage renderSceneInMemory(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                          bool checkOutput, RenderSession* session = nullptr);

// The memory the machine has available now (MemAvailable), or 0 when unknown.
unsigned long long availableMemoryBytes();

// Where a scene without an `output` line writes under `-o DIR/`: DIR/STEM.png, STEM the
// scene file's name without its extension (resolveOutput; --watch checks that folder before
// the scene parses).
std::string defaultOutputIn(const std::string& dir, const std::string& scenePath);

// The output path for a parsed scene, checked before rendering: first by request.onOutput,
// then for writing. A bad `output` line in the scene is a SceneError at that line; a bad
// override (`output` or `outputDir`) is an IoError.
std::string resolveOutput(const SceneDesc& scene, const RenderRequest& request);

}  // namespace vkrt
