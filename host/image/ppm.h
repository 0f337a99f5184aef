// Binary PPM (P6) files, written atomically (temporary file + rename), and their records
// read. The format of the course's guide: a text header, then the RGB bytes, row 0 at the top.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "image/image_file.h"   // RowWriter

namespace vkrt {

// Writes `image` as "P6\nW H\n255\n" followed by its bytes, to a temporary file beside `path`
// renamed over it. Throws IoError (Interrupted between rows); no temporary file is left behind.
void writePpmAtomic(const Image& image, const std::string& path);

// The table's functions (image/image_file.h, ImageFormat). openPpmRows writes the header
// ("P6", a "# KEYWORD TEXT" line per record, "W H", "255") and returns the writer of the
// rows as they are. isPpmFile: the file starts with "P6". readPpmText: the header's comment
// lines, after checking that the raster is all there; throws IoError.
std::unique_ptr<RowWriter> openPpmRows(int fd, int width, int height, const ImageRecords& records,
                                       const std::string& path);
bool isPpmFile(const std::string& path);
ImageRecords readPpmText(const std::string& path);

}  // namespace vkrt
