// `vkrt merge`: crops (images carrying a CropRecord) put back together into their full image,
// or sample batches of one render (PFM images carrying a SampleRecord) averaged. Knows nothing
// of rendering: the records say everything.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/radiance_image.h"
#include "image/samples.h"

namespace vkrt {

struct MergeReport {
  int tiles = 0;                 // tiles, or batches
  std::uint64_t gapPixels = 0;   // pixels no tile covers (black; only with allowGaps)
  SampleRecord samples;          // batches: the merged image's samples (and gamma)
  // Parts merged unchecked: those without a render identity (image/render_identity.h).
  std::vector<std::string> warnings;
  int width = 0, height = 0;     // tiles: the merged image's size
};

// Merging reads each input more than once (its records, then its pixels, so that only the
// tiles that share a row are held): throws IoError, naming the file, for an input that is
// missing, a folder, or not a regular file (a pipe, which can be read once, or a FIFO, whose
// opening would wait for a writer). Call it before the functions below.
void checkMergeInputsAreFiles(const std::vector<std::string>& paths);

// Reads every tile's records, checks them, then reads the tiles' pixels one at a time and
// places each where its record says. Throws UsageError (before anything is allocated for the
// merged image) for a set of tiles that does not make one image of one render: a tile without
// a record, a malformed one (fields out of range: a full image beyond kMaxRecordedImageEdge),
// one whose size is not its rectangle's, tiles of different full images, of different render
// identities (image/render_identity.h: another scene or settings) or samples records,
// overlapping tiles, and pixels no tile covers unless `allowGaps` (they stay black then).
// Tiles without a render identity are merged unchecked, with a warning in the report.
// Throws IoError, naming the file, when a tile cannot be read, is empty or is cut short.
// The merged image carries the tiles' samples record and identity when they have one.
Image mergeCrops(const std::vector<std::string>& tilePaths, bool allowGaps, MergeReport* report = nullptr);

}  // namespace vkrt

namespace vkrt {

// mergeCrops or mergeFloatCrops (by the tiles' kind) written to `outputPath` in its format
// (image/image_file.h; 8-bit tiles cannot make a .pfm: UsageError) without holding the merged
// image: after the same checks, each tile is read when the rows reach it and dropped after
// its last row, and bands of rows go to the file as they are assembled (image/row_sink.h).
// Memory: the tiles that share a row, not the image. The same errors; nothing is written on
// one.
void writeMergedCrops(const std::vector<std::string>& tilePaths, bool allowGaps, const std::string& outputPath,
                      MergeReport* report = nullptr);

// True when the files are sample batches rather than crops: every one carries a vkrt-samples
// record, and they lie at one place (the same crop record, or none). Throws IoError.
bool areSampleBatches(const std::vector<std::string>& paths);

// mergeCrops for tiles that are PFM files (linear float, as rendered): the same checks, and
// the tiles' samples record (path-traced tiles carry one), which must be the same in every
// tile, goes with the merged image (report->samples holds it, gamma 1 when none). Throws
// UsageError for a tile that is not a PFM (mergeCrops likewise refuses PFM tiles).
RadianceImage mergeFloatCrops(const std::vector<std::string>& tilePaths, bool allowGaps,
                              MergeReport* report = nullptr);

// Reads every batch and averages them weighted by their sample counts (image/samples.h:
// accumulateMean); the result carries the crop record (if any) and the union of the samples
// records. Throws UsageError for batches that are not of one render: one that is not a PFM
// (8-bit bytes are quantized: batches are averaged from linear float), one without a record or
// with a malformed one, sizes, places (crop records) or gammas that differ, and two that share
// a sample (the same seed and sample indices: the same numbers twice), render identities that
// differ (batches without one: a warning), a size beyond kMaxRecordedImageEdge; all before
// any raster is read. IoError when a file cannot be read, is empty or is cut short. The mean
// carries the identity when every batch has it.
RadianceImage mergeSampleBatches(const std::vector<std::string>& paths, MergeReport* report = nullptr);

}  // namespace vkrt
