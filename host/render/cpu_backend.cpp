// The CPU reference as a backend: the BVH, then each batch by the scene's technique, the
// Whitted model (renderReference) or a path integrator (renderPathReference).
#include <chrono>
#include <thread>

#include "cpu/path_reference.h"
#include "cpu/reference.h"
#include "render/backend.h"
#include "render/cpu_backend.h"
#include "util/timing.h"

namespace vkrt {
namespace {

class CpuBackend : public RenderBackend {
 public:
  CpuBackend(const RenderRequest& request, ProgressBar& progress, RenderReport& report, const SamplePlan& plan,
             const RowSink* rows)
      : request_(request), progress_(progress), report_(report), plan_(plan), rows_(rows) {}

  void build(SceneDesc& scene) override {
    scene_ = &scene;
    auto t0 = std::chrono::steady_clock::now();
    bvh_ = buildBvh(scene);
    report_.buildSeconds = secondsSince(t0);
    report_.bvhNodes = bvh_.nodes.size();
    report_.backend = "cpu";
    report_.threads =
        request_.threads > 0 ? request_.threads : static_cast<int>(std::thread::hardware_concurrency());
  }

  RadianceImage renderBatch(const SampleBatch& batch, const PixelProgress& px) override {
    RayCounts rays;
    RadianceImage image;
    if (scene_->path.integrator == Integrator::Raytracer) {
      CpuOptions o;
      o.threads = request_.threads;
      if (rows_) o.rows = *rows_;
      setBatch(o, request_, plan_, batch, batchProgress(plan_, progress_, px));
      image = renderReference(*scene_, bvh_, o, &rays);
    } else {
      PathOptions o;
      o.threads = request_.threads;
      o.stratified = request_.stratified;
      setBatch(o, request_, plan_, batch, batchProgress(plan_, progress_, px));
      image = renderPathReference(*scene_, bvh_, o, &rays);
    }
    report_.rays += rays;
    return image;
  }

 private:
  const RenderRequest& request_;
  ProgressBar& progress_;
  RenderReport& report_;
  const SamplePlan& plan_;
  const RowSink* rows_;
  const SceneDesc* scene_ = nullptr;
  Bvh bvh_;
};

}  // namespace

std::unique_ptr<RenderBackend> makeCpuBackend(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                                        const SamplePlan& plan, const RowSink* rows) {
  return std::make_unique<CpuBackend>(request, progress, report, plan, rows);
}

}  // namespace vkrt
