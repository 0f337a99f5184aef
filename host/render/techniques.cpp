// The rendering techniques: the Whitted model (cpu/reference, gpu/vulkan_renderer and
// shaders/raytrace.comp), the path integrators (cpu/path_reference, gpu/vulkan_path_renderer
// and shaders/pathtrace.comp) and the views (cpu/<view>, shaders/<view>.comp on the Whitted
// host), each row with its glue on both backends.
#include "render/techniques.h"

#include <string>
#include <utility>

#include "cpu/normals.h"
#include "cpu/path_reference.h"
#include "cpu/reference.h"
#include "gpu/vulkan_path_renderer.h"
#include "gpu/vulkan_renderer.h"
#include "util/errors.h"

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
  o.wideBvh = in.request.wideBvh;
  setBatch(o, in.request, in.plan, batch, std::move(progress));
  return o;
}

// ---- the Whitted model: one deterministic sample; a batch streams its rows when asked ----------

bool whittedRenders(const SceneDesc& scene) { return scene.path.integrator == Integrator::Raytracer; }

// A technique on the Whitted host: raytrace.comp, or a view's shaders/<shader>.comp.
VulkanTechnique onWhittedHost(const BackendInputs& in, std::string_view shader) {
  auto options = [in, shader](const SampleBatch& batch, PixelProgress pixels) {
    VulkanOptions o = vulkanOptions<VulkanOptions>(in, batch, std::move(pixels));
    o.shader = shader;
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

VulkanTechnique whittedVulkan(const BackendInputs& in) { return onWhittedHost(in, "raytrace"); }

// A technique of one deterministic sample a pixel on the CPU: `render` as renderReference.
template <RadianceImage (*render)(const SceneDesc&, const Bvh&, const CpuOptions&, RayCounts*)>
CpuTechnique eachPixelOnceCpu(const BackendInputs& in) {
  return [in](const SceneDesc& scene, const Bvh& bvh, const SampleBatch& batch, PixelProgress px, RayCounts* rays) {
    CpuOptions o;
    o.threads = in.request.threads;
    if (in.rows) o.rows = *in.rows;
    setBatch(o, in.request, in.plan, batch, std::move(px));
    return render(scene, bvh, o, rays);
  };
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

// ---- the views: one deterministic sample a pixel, their shaders on the Whitted host --------

VulkanTechnique normalsVulkan(const BackendInputs& in) { return onWhittedHost(in, "normals"); }

// The rows: the scene's own techniques in the order they are asked (the last takes every
// scene the others do not), then the views.
const Technique kTechniques[] = {
    {"whitted", nullptr, whittedRenders, false, eachPixelOnceCpu<renderReference>, whittedVulkan},
    {"path", nullptr, pathRenders, true, pathCpu, pathVulkan},
    {"normals", "each pixel's surface normal n as the colour n * 0.5 + 0.5", nullptr, false,
     eachPixelOnceCpu<renderNormals>, normalsVulkan},
};

}  // namespace

const Technique* viewNamed(std::string_view name) {
  for (const Technique& t : kTechniques)
    if (t.view && name == t.name) return &t;
  return nullptr;
}

std::vector<const Technique*> views() {
  std::vector<const Technique*> out;
  for (const Technique& t : kTechniques)
    if (t.view) out.push_back(&t);
  return out;
}

const Technique& techniqueFor(const SceneDesc& scene, std::string_view view) {
  if (!view.empty()) {
    if (const Technique* t = viewNamed(view)) return *t;
    throw InternalError("no view named '" + std::string(view) + "'");   // the option's value is checked
  }
  const Technique* last = nullptr;
  for (const Technique& t : kTechniques) {
    if (t.view) continue;
    if (t.renders(scene)) return t;
    last = &t;
  }
  return *last;
}

}  // namespace vkrt
