// params.glsl: the render's parameters (GpuRenderParams) as both compute shaders read them. The
// host writes them to a storage buffer, and main's first line copies them into the private
// `params` (loadParams), which the rest of the shader reads.
//
// Why a storage buffer and a copy: lavapipe (Mesa 22.3) may inline up to four values of a
// uniform block that decide a branch or bound a loop, and then compile the shader again for
// each new set of them; it did so with the path shader's camera, a compile for every scene
// (bench/README.md, "Parameters in storage buffers"). It inlines nothing of a storage buffer.
// And the copy costs fewer instructions than a read where each value is used.

layout(std430, binding = kBindingParams) readonly buffer Params { GpuRenderParams paramsStored; };
GpuRenderParams params;

void loadParams() { params = paramsStored; }
