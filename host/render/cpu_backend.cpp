// The CPU reference as a backend: the BVH, then each batch by the scene's technique
// (render/techniques.h).
#include <chrono>
#include <thread>

#include "render/backend.h"
#include "render/cpu_backend.h"
#include "render/techniques.h"
#include "util/timing.h"

namespace vkrt {
namespace {

class CpuBackend : public RenderBackend {
 public:
  using RenderBackend::RenderBackend;

  void build(SceneDesc& scene) override {
    scene_ = &scene;
    technique_ = techniqueFor(scene, in_.request.view).cpu(in_);
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
    RadianceImage image = technique_(*scene_, bvh_, batch, batchProgress(in_.plan, in_.progress, px), &rays);
    in_.report.rays += rays;
    return image;
  }

 private:
  const SceneDesc* scene_ = nullptr;
  Bvh bvh_;
  CpuTechnique technique_;
};

}  // namespace

std::unique_ptr<RenderBackend> makeCpuBackend(const BackendInputs& in) { return std::make_unique<CpuBackend>(in); }

}  // namespace vkrt
