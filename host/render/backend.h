// The seam between the pipeline (render.cpp) and the backends: a RenderBackend validates a scene
// against its own limits, builds what it renders from, and renders sample batches of the
// scene's technique. render.cpp asks one (makeBackend) and knows nothing of which technique
// or device renders; the backends take the scene's technique from render/techniques.h.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>

#include "image/radiance_image.h"
#include "image/row_sink.h"
#include "render/progressive.h"
#include "render/render.h"
#include "scene/scene_desc.h"

namespace vkrt {

class ProgressBar;

// What every batch of a render shares: its samples as batches (render/progressive.h), and the
// generator's seed.
struct SamplePlan {
  ProgressiveOptions progressive;
  std::uint32_t seed = 0;
};

using PixelProgress = std::function<void(std::uint64_t, std::uint64_t)>;

// What every backend is given: the request, the bar, the report it fills, the plan of its
// batches, and where a streamed render's rows go (may be null).
struct BackendInputs {
  const RenderRequest& request;
  ProgressBar& progress;
  RenderReport& report;
  const SamplePlan& plan;
  const RowSink* rows;
};

class RenderBackend {
 public:
  explicit RenderBackend(const BackendInputs& in) : in_(in) {}
  virtual ~RenderBackend() = default;
  // Builds what the batches render from (the BVH; the device, the GPU's arrays and pipeline),
  // reporting its times; the render's seconds so far (a device's setup) in renderSeconds. May
  // free the scene's shapes once they are no longer read; `scene` must outlive the backend.
  virtual void build(SceneDesc& scene) = 0;
  // One batch of samples; `pixelProgress` as BatchRenderer's.
  virtual RadianceImage renderBatch(const SampleBatch& batch, const PixelProgress& pixelProgress) = 0;
  // After the last batch: the report's totals.
  virtual void finish() {}

 protected:
  BackendInputs in_;
};

// The backend `request.backend` names, for batches of `plan`; with `rows`, a render of one
// batch streams its bands there. It reports into `report`; `vulkan` lends the Vulkan context.
// The objects must outlive the backend.
std::unique_ptr<RenderBackend> makeBackend(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                                           RenderSession& vulkan, const SamplePlan& plan, const RowSink* rows);

// Throws SceneError where `scene` is beyond what `request.backend` can render (said at the
// scene's line, before anything is rendered, also by --dry-run). Opens no device.
void validateForBackend(const RenderRequest& request, const SceneDesc& scene);

// The settings every renderer's options share (CpuOptions, PathOptions, VulkanOptions,
// VulkanPathOptions), set for one batch: its samples, the seed, the crop, progress, and the plan's
// stop (Ctrl-C, or a time limit).
template <class Options>
void setBatch(Options& o, const RenderRequest& request, const SamplePlan& plan, const SampleBatch& batch,
              PixelProgress progress) {
  o.seed = plan.seed;
  o.firstSample = static_cast<decltype(o.firstSample)>(batch.firstSample);
  o.sampleCount = batch.count;
  o.crop = request.crop;
  o.progress = std::move(progress);
  o.stop = plan.progressive.stop;   // a signal, or the request's time limit (render.cpp)
}

// One batch's progress on the bar: a Whitted render (one batch) shows pixels, a progressive
// one samples (renderProgressive maps pixels into them).
PixelProgress batchProgress(const SamplePlan& plan, ProgressBar& bar, const PixelProgress& pixelProgress);

}  // namespace vkrt
