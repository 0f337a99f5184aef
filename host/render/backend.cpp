// The backend a render asks for, and what every backend's batches share.
#include "render/backend.h"

#include "render/cpu_backend.h"
#include "render/vulkan_backend.h"
#include "render/progress.h"
#include "util/interrupt.h"

namespace vkrt {

std::unique_ptr<RenderBackend> makeBackend(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                                     RenderSession& vulkan, const SamplePlan& plan, const RowSink* rows) {
  const BackendInputs in{request, progress, report, plan, rows};
  if (request.backend == Backend::Cpu) return makeCpuBackend(in);
  return makeVulkanBackend(in, vulkan);
}

void validateForBackend(const RenderRequest& request, const SceneDesc& scene) {
  if (request.backend == Backend::Vulkan) validateForVulkan(scene);
}

PixelProgress batchProgress(const SamplePlan& plan, ProgressBar& bar, const PixelProgress& pixelProgress) {
  const bool samples = plan.progressive.progress != nullptr;
  return [samples, &bar, pixelProgress](std::uint64_t done, std::uint64_t total) {
    if (samples && pixelProgress)
      pixelProgress(done, total);
    else if (!samples)
      bar.update(done, total);
    waitForSignalIfTesting("render");
  };
}

}  // namespace vkrt
