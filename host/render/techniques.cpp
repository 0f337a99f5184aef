// The rendering techniques: the Whitted model (cpu/reference, gpu/vulkan_renderer and
// shaders/raytrace.comp) and the path integrators (cpu/path_reference, gpu/vulkan_path_renderer
// and shaders/pathtrace.comp), each row with its glue on both backends.
#include "render/techniques.h"

#include <utility>

#include "cpu/path_reference.h"
#include "cpu/reference.h"
#include "gpu/vulkan_path_renderer.h"
#include "gpu/vulkan_renderer.h"

namespace vkrt {
namespace {

// The settings both Vulkan renderers' options share (VulkanOptions, VulkanPathOptions), for one
// batch: the request's step budget, reads and variant, and setBatch's.
template <class Options>
Options vulkanOptions(const BackendInputs& in, const SampleBatch& batch, PixelProgress progress) {
  Options o;
  o.stepBudget = in.request.stepBudget;
  o.reads = in.request.reads;
  o.variant = in.request.variant;
  setBatch(o, in.request, in.plan, batch, std::move(progress));
  return o;
}

// ---- the Whitted model: one deterministic sample; a batch streams its rows when asked ----------

bool whittedRenders(const SceneDesc& scene) { return scene.path.integrator == Integrator::Raytracer; }

CpuTechnique whittedCpu(const BackendInputs& in) {
  return [in](const SceneDesc& scene, const Bvh& bvh, const SampleBatch& batch, PixelProgress px, RayCounts* rays) {
    CpuOptions o;
    o.threads = in.request.threads;
    if (in.rows) o.rows = *in.rows;
    setBatch(o, in.request, in.plan, batch, std::move(px));
    return renderReference(scene, bvh, o, rays);
  };
}

VulkanTechnique whittedVulkan(const BackendInputs& in) {
  auto options = [in](const SampleBatch& batch, PixelProgress pixels) {
    VulkanOptions o = vulkanOptions<VulkanOptions>(in, batch, std::move(pixels));
    o.cutoff = in.request.cutoff;
    if (in.rows) o.rows = *in.rows;
    return o;
  };
  return {[options](const Context& context, const GpuScene& arrays, const SampleBatch& first, bool eachOnce) {
            prepareVulkanPipeline(context, arrays, options(first, {}), eachOnce);
          },
          [options](const Context& context, const GpuScene& scene, const SampleBatch& batch, PixelProgress px,
                    RayCounts* rays, VulkanTimings* timings) {
            return renderVulkan(context, scene, options(batch, std::move(px)), rays, timings);
          }};
}

// ---- the path integrators: sample batches; on the GPU they share one upload of the scene ------

bool pathRenders(const SceneDesc&) { return true; }

CpuTechnique pathCpu(const BackendInputs& in) {
  return [in](const SceneDesc& scene, const Bvh& bvh, const SampleBatch& batch, PixelProgress px, RayCounts* rays) {
    PathOptions o;
    o.threads = in.request.threads;
    o.stratified = in.request.stratified;
    setBatch(o, in.request, in.plan, batch, std::move(px));
    return renderPathReference(scene, bvh, o, rays);
  };
}

VulkanTechnique pathVulkan(const BackendInputs& in) {
  auto options = [in](const SampleBatch& batch, PixelProgress pixels) {
    VulkanPathOptions o = vulkanOptions<VulkanPathOptions>(in, batch, std::move(pixels));
    o.stratified = in.request.stratified;
    return o;
  };
  auto shared = std::make_shared<std::unique_ptr<VulkanPathRender>>();   // made by the first batch
  return {[options](const Context& context, const GpuScene& arrays, const SampleBatch& first, bool eachOnce) {
            prepareVulkanPathPipeline(context, arrays, options(first, {}), eachOnce);
          },
          [options, shared](const Context& context, const GpuScene& scene, const SampleBatch& batch, PixelProgress px,
                            RayCounts* rays, VulkanTimings* timings) {
            if (!*shared) *shared = std::make_unique<VulkanPathRender>(context, scene);
            return (*shared)->render(options(batch, std::move(px)), rays, timings);
          }};
}

// The rows, in the order they are asked; the last takes every scene.
const Technique kTechniques[] = {
    {"whitted", whittedRenders, whittedCpu, whittedVulkan},
    {"path", pathRenders, pathCpu, pathVulkan},
};

}  // namespace

const Technique& techniqueFor(const SceneDesc& scene) {
  for (const Technique& t : kTechniques)
    if (t.renders(scene)) return t;
  return kTechniques[std::size(kTechniques) - 1];
}

}  // namespace vkrt
