// vkrt diff A B (host/cli/diff_images.h).
#include "cli/diff_images.h"

#include <optional>

#include "cli/comparison_report.h"
#include "cli/run_files.h"
#include "image/image_read.h"

namespace vkrt {

// vkrt diff A B: both images are inputs, the heatmap (--diff) the output.
int diffImages(const DiffOptions& options) {
  RunFiles files;
  files.addInput(options.a, "image A");
  files.addInput(options.b, "image B");
  claimHeatmap(options.comparison, files);
  AnyImage a = readAnyImage(options.a);   // A first: its error, if both have one
  AnyImage b = readAnyImage(options.b);
  std::optional<LinearDifference> linear;
  if (a.radiance && b.radiance) linear = linearDifference(*a.radiance, *b.radiance);
  auto bytes = [](const AnyImage& image) { return image.radiance ? asBytes(*image.radiance) : image.bytes; };
  // Two float images: HDR-FLIP of their radiance; otherwise LDR-FLIP of the 8-bit images.
  const bool hdr = a.radiance && b.radiance;
  return reportComparison(options.comparison, bytes(a), bytes(b), options.a + " vs " + options.b, linear,
                          hdr ? &*a.radiance : nullptr, hdr ? &*b.radiance : nullptr);
}

}  // namespace vkrt
