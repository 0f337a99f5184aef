// The one conversion from linear radiance to bytes, at output: doc/scene-format.md, "Conventions"'s quantization
// after the `gamma` encoding of doc/path-tracing.md, "Commands". Knows nothing of rendering.
#pragma once

#include <cstddef>
#include <cstdint>

#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// byte = floor(255 clamp(c^(1/gamma), 0, 1)); NaN and c <= 0 give 0, +infinity 255.
// The product and the floor are taken in float, as the shader's exactness cut-off reasons
// (raytrace.comp, restCannotChangePixel): for gamma 1 a byte is floor(min(c, 1) * 255.0f).
// The power (gamma != 1 only) is taken in double and rounded to float.
std::uint8_t encodeChannel(float c, double gamma);

// `count` channels through encodeChannel, from `in` to `out`.
void encodeRow(const float* in, std::size_t count, double gamma, std::uint8_t* out);

// Every pixel through encodeChannel; the records (text) are kept. gamma > 0.
Image encodeImage(const RadianceImage& image, double gamma);

}  // namespace vkrt
