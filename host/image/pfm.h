// PFM (Portable Float Map) files: a RadianceImage written as it is, unquantized, and read back.
// Knows nothing of rendering.
//
// The format: "PF\n" (colour), "W H\n", "-1.0\n" (negative: little-endian floats), then W x H
// RGB float32 triples, rows from the bottom of the image to the top. PFM has no comments, so
// the image's records (RadianceImage::text: the crop's place, the samples of a batch) follow
// the raster as a trailer: the line "#vkrt-records" and then one "KEYWORD TEXT" line each.
// A reader that reads the header and then W x H x 3 floats, as the format defines, never sees
// it; a file without records has none and is plain PFM.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "image/byte_sink.h"
#include "image/image_file.h"   // RowWriter
#include "image/radiance_image.h"

namespace vkrt {

// A PFM written into `sink` as its rows come, top rows first: the header at construction,
// each band at its place with ByteSink::writeAt (the raster is the bottom row first, so the
// top band goes at the end), the records' trailer at finish(). Memory: a row. Throws IoError
// (the sink's), Interrupted, InternalError for rows outside the image or missing.
class PfmRowWriter : public RowWriter {
 public:
  PfmRowWriter(ByteSink& sink, int width, int height,
               const std::vector<std::pair<std::string, std::string>>& records);
  // Rows [y0, y0 + band.height) of the image (band.width == width).
  void radianceRows(int y0, const RadianceImage& band) override;
  void finish() override;

 private:
  ByteSink& sink_;
  int width_, height_;
  std::vector<std::pair<std::string, std::string>> records_;
  std::uint64_t headerBytes_ = 0, written_ = 0;
  std::vector<std::uint32_t> row_;
};

// A PfmRowWriter, as the table's openRows (image/image_file.h, ImageFormat).
std::unique_ptr<RowWriter> openPfmRows(ByteSink& sink, int width, int height, const ImageRecords& records,
                                       const std::string& path);

// Writes `image` (and its records) atomically. Throws IoError (and Interrupted).
void writePfmAtomic(const RadianceImage& image, const std::string& path);

// Reads a PFM: colour ("PF") or grey ("Pf", each value copied to the three channels), either
// byte order, any scale; the trailer's records into `text`. `samples` is left at 1 (the
// caller reads it from a record). Throws IoError for a file that cannot be read, is no PFM, or
// is cut short (checked before the raster is allocated).
RadianceImage readPfm(const std::string& path);

// A PFM's size and records, without its pixels (`rgb` stays empty), after checking that the
// raster is all there. Throws IoError.
RadianceImage readPfmInfo(const std::string& path);

// The records of a PFM's trailer (readImageText for .pfm files). Throws IoError.
std::vector<std::pair<std::string, std::string>> readPfmText(const std::string& path);

// True when the file starts as a PFM ("PF" or "Pf" and a line end).
bool isPfmFile(const std::string& path);

}  // namespace vkrt
