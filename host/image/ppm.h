// Binary PPM (P6) files, written atomically (temporary file + rename), their records read, and
// binary Netpbm images (P6, and P5 grey) of any maxval read as 8-bit RGB. The format of the
// course's guide: a text header, then the RGB bytes, row 0 at the top.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/byte_sink.h"
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
std::unique_ptr<RowWriter> openPpmRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path);
bool isPpmFile(const std::string& path);
ImageRecords readPpmText(const std::string& path);

// Whether `head` (a file's first bytes, at least two) starts a binary Netpbm image vkrt reads:
// "P6" (RGB) or "P5" (grey).
bool isBinaryNetpbm(const unsigned char* head, std::size_t size);

// Reads a binary Netpbm image from `in`, whose first two bytes ("P6" or "P5", `kind` the
// digit) have been read already, as the Netpbm spec says: any maxval from 1 to 65535, two bytes a sample
// (most significant first) above 255; each sample scaled to 8 bits as round(v * 255 / maxval)
// (and one above maxval as 255), grey copied to the three channels. Throws IoError naming
// `path`: a malformed header, a maxval out of range, an image with no pixels, a raster cut
// short, a failed read (with the system's reason).
Image readBinaryNetpbm(std::FILE* in, char kind, const std::string& path);
// Its width and height alone, from its header, checked as readBinaryNetpbm checks them.
void readBinaryNetpbmSize(std::FILE* in, char kind, const std::string& path, int& width, int& height);

}  // namespace vkrt
