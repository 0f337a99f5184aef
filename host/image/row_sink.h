// Streaming a render to its file: the renderers hand finished bands of rows to a RowSink, and
// writeImageStreamed encodes each band as it comes, so that neither the float image nor its
// bytes are ever held whole. Knows nothing of rendering.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

// Takes rows [y0, y0 + band.height) of an image (band.width its width; y0 relative to the
// image's top). A renderer calls it top to bottom, each row once; it may throw (IoError,
// Interrupted), which stops the render.
using RowSink = std::function<void(int y0, const RadianceImage& band)>;

// Writes a `width` x `height` image with `records` to `path`, atomically, in the format of
// imageFormatFor(path) (image/image_file.h): `render(sink)` must call sink with every row;
// for an 8-bit format each band is encoded with `gamma` as it comes, a linear-float format
// takes it as it is. Throws what `render` throws (nothing is written then: the temporary file goes),
// IoError, and InternalError when `render` returns without every row.
void writeImageStreamed(const std::string& path, double gamma, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const RowSink&)>& render);

// The same for 8-bit rows (an image already quantized: merged 8-bit tiles), as they are.
using ByteRowSink = std::function<void(int y0, const Image& band)>;

// writeImageStreamed for 8-bit rows, into an 8-bit format (a linear-float name is a
// UsageError, as writeImageAtomic's for an Image, before anything is created).
void writeBytesStreamed(const std::string& path, int width, int height,
                        const std::vector<std::pair<std::string, std::string>>& records,
                        const std::function<void(const ByteRowSink&)>& render);

}  // namespace vkrt
