// The CPU reference renderer as a RenderBackend (render/backend.h).
#pragma once

#include <memory>

#include "render/backend.h"

namespace vkrt {

std::unique_ptr<RenderBackend> makeCpuBackend(const BackendInputs& in);

}  // namespace vkrt
