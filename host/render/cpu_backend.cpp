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
  using RenderBackend::RenderBackend;

  void build(SceneDesc& scene) override {
    scene_ = &scene;
    auto t0 = std::chrono::steady_clock::now();
    bvh_ = buildBvh(scene);
    in_.report.buildSeconds = secondsSince(t0);
    in_.report.bvhNodes = bvh_.nodes.size();
    in_.report.backend = "cpu";
    in_.report.threads =
        in_.request.threads > 0 ? in_.request.threads : static_cast<int>(std::thread::hardware_concurrency());
  }

  RadianceImage renderBatch(const SampleBatch& batch, const PixelProgress& px) override {
    RayCounts rays;
    RadianceImage image;
    if (scene_->path.integrator == Integrator::Raytracer) {
      CpuOptions o;
      o.threads = in_.request.threads;
      if (in_.rows) o.rows = *in_.rows;
      setBatch(o, in_.request, in_.plan, batch, batchProgress(in_.plan, in_.progress, px));
      image = renderReference(*scene_, bvh_, o, &rays);
    } else {
      PathOptions o;
      o.threads = in_.request.threads;
      o.stratified = in_.request.stratified;
      setBatch(o, in_.request, in_.plan, batch, batchProgress(in_.plan, in_.progress, px));
      image = renderPathReference(*scene_, bvh_, o, &rays);
    }
    in_.report.rays += rays;
    return image;
  }

 private:
  const SceneDesc* scene_ = nullptr;
  Bvh bvh_;
};

}  // namespace

std::unique_ptr<RenderBackend> makeCpuBackend(const BackendInputs& in) { return std::make_unique<CpuBackend>(in); }

}  // namespace vkrt
