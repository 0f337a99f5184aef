// The CPU reference renderer as a RenderBackend (render/backend.h).
#pragma once

#include <memory>

#include "render/backend.h"

namespace vkrt {

std::unique_ptr<RenderBackend> makeCpuBackend(const RenderRequest& request, ProgressBar& progress, RenderReport& report,
                                        const SamplePlan& plan, const RowSink* rows);

}  // namespace vkrt
