// The Vulkan renderers as a RenderBackend (render/backend.h), and their own limits of a scene.
#pragma once

#include <memory>

#include "render/backend.h"

namespace vkrt {

std::unique_ptr<RenderBackend> makeVulkanBackend(const BackendInputs& in, RenderSession& session);

// Throws SceneError, at the scene's lightsamples line, where the path shader cannot draw the
// light samples of a vertex (lightSlotsProblem). Opens no device.
void validateForVulkan(const SceneDesc& scene);

}  // namespace vkrt
