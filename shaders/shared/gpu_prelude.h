// gpu_prelude.h: what lets the gpu_*.h headers be valid C++20 (host/) and valid GLSL 450
// (shaders/) at once: the C++ names of GLSL's types, and macros for constants, functions,
// layout assertions and the C++ namespace. The headers it serves: no templates, no methods,
// no ';' after a macro.
#ifndef VKRT_GPU_PRELUDE_H
#define VKRT_GPU_PRELUDE_H

#ifdef __cplusplus
#  include <cstddef>
#  include <cstdint>
#  include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
}  // namespace gpu
#  define GPU_BEGIN namespace gpu {
#  define GPU_END }
#  define GPU_CONST inline constexpr
#  define GPU_FN inline
#  define GPU_ASSERT_SIZE(T, n) static_assert(sizeof(T) == (n), #T " size drifted");
#  define GPU_ASSERT_OFFSET(T, m, n) static_assert(offsetof(T, m) == (n), #T "." #m " moved");
#else
#  define GPU_BEGIN
#  define GPU_END
#  define GPU_CONST const
#  define GPU_FN
#  define GPU_ASSERT_SIZE(T, n)
#  define GPU_ASSERT_OFFSET(T, m, n)
#endif

#endif  // VKRT_GPU_PRELUDE_H
