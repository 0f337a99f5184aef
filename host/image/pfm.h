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

#include <string>
#include <utility>
#include <vector>

#include "image/radiance_image.h"

namespace vkrt {

// Writes `image` (and its records) atomically. Throws IoError (and Interrupted).
void writePfmAtomic(const RadianceImage& image, const std::string& path);

// Reads a PFM: colour ("PF") or grey ("Pf", each value copied to the three channels), either
// byte order, any scale; the trailer's records into `text`. `samples` is left at 1 (the
// caller reads it from a record). Throws IoError for a file that cannot be read or is no PFM.
RadianceImage readPfm(const std::string& path);

// The records of a PFM's trailer (readImageText for .pfm files). Throws IoError.
std::vector<std::pair<std::string, std::string>> readPfmText(const std::string& path);

// True when the file starts as a PFM ("PF" or "Pf" and a line end).
bool isPfmFile(const std::string& path);

}  // namespace vkrt
