// vkrt merge: crops into their full image, or sample batches into their mean
// (host/cli/merge_images.h).
#include "cli/merge_images.h"

#include <cstdio>

#include "cli/exit_status.h"
#include "cli/run_files.h"
#include "util/counted.h"
#include "image/atomic_file.h"
#include "image/image_file.h"
#include "image/merge.h"

namespace vkrt {

// vkrt merge: the tiles are inputs, the merged image the output.
int mergeImages(const MergeOptions& options) {
  RunFiles files;
  for (const std::string& tile : options.tiles) files.addInput(tile, "the tile");
  files.addOutput(options.output, "the merged image");
  checkOutputWritable(options.output);
  checkMergeInputsAreFiles(options.tiles);
  MergeReport merged;
  auto printWarnings = [&] {   // -q leaves warnings out, as a scene's
    if (!options.quiet)
      for (const std::string& w : merged.warnings) std::fprintf(stderr, "vkrt: warning: %s\n", w.c_str());
  };
  if (areSampleBatches(options.tiles)) {
    RadianceImage mean = mergeSampleBatches(options.tiles, &merged);
    printWarnings();
    writeImageAtomic(mean, options.output, merged.samples.gamma);
    if (!options.quiet)
      std::fprintf(stderr, "vkrt: averaged %s (%s per pixel) into %s (%dx%d)\n",
                   counted(merged.tiles, "batch", "batches").c_str(),
                   counted(merged.samples.total(), "sample", "samples").c_str(), options.output.c_str(),
                   mean.width, mean.height);
    return kExitOk;
  }
  writeMergedCrops(options.tiles, options.allowGaps, options.output, &merged);
  printWarnings();
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: merged %s into %s (%dx%d)%s\n", counted(merged.tiles, "tile", "tiles").c_str(),
                 options.output.c_str(), merged.width, merged.height,
                 merged.gapPixels ? (", " + counted(merged.gapPixels, "pixel", "pixels") + " left black").c_str()
                                  : "");
  return kExitOk;
}

}  // namespace vkrt
