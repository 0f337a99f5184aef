// JPEG files, read (vkrt writes none) with libjpeg-turbo, Debian's JPEG library, which is
// fuzzed upstream; stb_image's JPEG decoder wrote past a Huffman table's end on a crafted file
// (found by tests/fuzz/image_fuzzer.cpp on Debian 12's stb). image_file.cpp's readImage and
// readImageSize come here for a file that starts with a JPEG's marker.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "image/image.h"

namespace vkrt {

// Whether `head` (a file's first bytes) starts as a JPEG does (FF D8 FF).
bool isJpegHead(const unsigned char* head, std::size_t size);

// The JPEG in `file`, whose first `headSize` bytes, `head`, have been read from it already
// (the rest is read from `file`, which may be a FIFO). A JPEG that ends early decodes with the
// rest grey, as libjpeg fills it. Throws IoError ("cannot read image 'PATH': REASON", the
// library's reason), and Interrupted (polled per row).
Image readJpeg(std::FILE* file, const unsigned char* head, std::size_t headSize, const std::string& path);

// Its size, from its header alone. Throws IoError.
void readJpegSize(std::FILE* file, const unsigned char* head, std::size_t headSize, const std::string& path,
                  int& width, int& height);

}  // namespace vkrt
