// The Vulkan renderers as a backend: the device, the GPU's arrays (the first batch's pipeline
// made while the BVH builds), then each batch by the scene's technique (render/techniques.h).
#include "render/vulkan_backend.h"

#include <chrono>
#include <exception>
#include <string>
#include <vector>

#include "gpu/vulkan_path_renderer.h"   // lightSlotsProblem
#include "gpu/vulkan_settings.h"       // VulkanTimings, addBatchTimings
#include "render/techniques.h"
#include "scene/diagnostic.h"
#include "scene/emitters.h"
#include "scene/flatten.h"
#include "scene/wide_bvh.h"
#include "scene/shapes/shape.h"
#include "util/timing.h"

namespace vkrt {
namespace {

class VulkanBackend : public RenderBackend {
 public:
  VulkanBackend(const BackendInputs& in, RenderSession& session) : RenderBackend(in), session_(session) {}

  // Frees the scene's shapes once they are flattened: nothing after that reads them (152 bytes
  // a triangle, 150 MB for a million, held through the upload and render otherwise).
  void build(SceneDesc& scene) override {
    auto t0 = std::chrono::steady_clock::now();
    // The device first: without one there is nothing to build for.
    bool made = false;
    context_ = &session_.context(in_.request, made);
    if (made) {
      in_.report.instanceSeconds = context_->instanceSeconds();
      in_.report.deviceSeconds = context_->deviceSeconds();
    }
    in_.report.backend = std::string("vulkan (") + context_->properties().deviceName + ")";
    in_.report.renderSeconds = secondsSince(t0);   // the device's setup counts as the render's
    technique_ = techniqueFor(scene, in_.request.view).vulkan(in_);
    pipelinesBefore_ = context_->pipelines().made();

    t0 = std::chrono::steady_clock::now();
    // The first batch's pipeline is made while the BVH builds (lavapipe's pipeline creation:
    // bench/README.md, "Fixed cost of the Vulkan backend"), from the scene's arrays (and the scene, which both threads only read); the
    // batch takes it then. A failure there is the batch's to meet again, in its place.
    double ahead = 0;
    gpuScene_ = flatten(scene, [&](const GpuScene& arrays) {
      const auto start = std::chrono::steady_clock::now();
      try {
        // (whether every primitive is in the BVH matters only to a scene small enough to test all)
        const bool eachPrimitiveOnce = primitiveCount(arrays) > gpu::kTestAllMaxPrims || !shapes::anyNeverHit(scene);
        technique_.prepare(*context_, arrays, firstBatch(in_.plan.progressive), eachPrimitiveOnce);
      } catch (const std::exception&) {
      }
      ahead = secondsSince(start);
    });
    if (in_.request.wideBvh) collapseToFourWide(gpuScene_.bvh);
    in_.report.buildSeconds = secondsSince(t0);
    in_.report.pipelineAheadSeconds = ahead;
    in_.report.bvhNodes = gpuScene_.bvh.nodes.size();
#define VKRT_SHAPE_FREE(Type, member, name, kind, GpuType, binding) std::vector<Type>().swap(scene.member);
    VKRT_SHAPES(VKRT_SHAPE_FREE)
#undef VKRT_SHAPE_FREE
  }

  RadianceImage renderBatch(const SampleBatch& batch, const PixelProgress& px) override {
    RayCounts rays;
    VulkanTimings timings;
    RadianceImage image =
        technique_.render(*context_, gpuScene_, batch, batchProgress(in_.plan, in_.progress, px), &rays, &timings);
    in_.report.rays += rays;
    addBatchTimings(in_.report.vulkan, timings, batch.firstSample == in_.plan.progressive.firstSample);
    return image;
  }

  void finish() override { in_.report.pipelinesMade = context_->pipelines().made() - pipelinesBefore_; }

 private:
  RenderSession& session_;
  const Context* context_ = nullptr;
  GpuScene gpuScene_;
  VulkanTechnique technique_;   // declared after gpuScene_, which what it keeps reads
  std::size_t pipelinesBefore_ = 0;
};

}  // namespace

std::unique_ptr<RenderBackend> makeVulkanBackend(const BackendInputs& in, RenderSession& session) {
  return std::make_unique<VulkanBackend>(in, session);
}

// (The emitters, a pass over every primitive, are looked for only when they would pass it.)
void validateForVulkan(const SceneDesc& scene) {
  if (scene.path.integrator == Integrator::Raytracer) return;
  const gpu::GpuPathParams path = pathParams(scene);
  std::string problem = lightSlotsProblem(path, false);
  if (problem.empty() && !lightSlotsProblem(path, true).empty() && !collectEmitters(scene).prims.empty())
    problem = lightSlotsProblem(path, true);
  if (!problem.empty()) throw SceneError({Diagnostic{scene.sourcePath, scene.path.lightSamplesLine, problem}});
}

}  // namespace vkrt
