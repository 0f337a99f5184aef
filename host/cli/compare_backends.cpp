// vkrt --compare SCENE: the scene rendered by both backends and the two images compared
// (host/cli/compare_backends.h).
#include "cli/compare_backends.h"

#include <cstdio>

#include "cli/comparison_report.h"
#include "cli/exit_status.h"
#include "compare/image_check.h"
#include "cli/render_report.h"
#include "cli/run_files.h"
#include "cli/warning_printers.h"
#include "image/encode.h"
#include "util/json.h"

namespace vkrt {

// --compare: both backends in turn, nothing written; the total time of each and their
// difference (stdout), each one's breakdown (stderr) only with --stats. Exit 5 when a
// threshold is exceeded.
int compareBackends(const RenderOptions& o) {
  RunFiles files;
  files.addInput(o.request.scenePath, "the scene file");
  claimHeatmap(o.comparison, files);
  RenderReport reports[2];
  Image images[2];
  RadianceImage radiance[2];   // for HDR-FLIP: the two renders before their encoding
  const Backend backends[2] = {Backend::Vulkan, Backend::Cpu};
  for (int i = 0; i < 2; ++i) {
    RenderRequest request = o.request;
    request.backend = backends[i];
    request.onWarnings = warningPrinter(o.quiet || i > 0);   // the same scene twice: once
    request.onOptionWarning = optionWarningPrinter(o.quiet || i > 0);
    ProgressBar progress(!o.quiet && !o.comparison.json);
    radiance[i] = renderSceneInMemory(request, progress, reports[i], false);
    images[i] = encodeImage(radiance[i], reports[i].gamma);
    if (o.stats && !o.comparison.json && !o.quiet) printStats(request, reports[i]);
    warnNonFinite(o.quiet, reports[i], i == 0 ? "vulkan" : "cpu");
  }
  // The 8-bit figures compare the two encoded images; FLIP, the two renders' radiance (HDR-FLIP).
  ImageComparison c =
      compareImages(images[0], images[1], o.comparison.thresholds.pixelsPerDegree, &radiance[0], &radiance[1]);
  std::vector<std::string> failures = failedThresholds(c.diff, c.flip, o.comparison.thresholds);
  if (!o.comparison.thresholds.any()) failures.clear();   // --compare reports; it gates only when asked to
  auto total = [](const RenderReport& r) { return r.parseSeconds + r.buildSeconds + r.renderSeconds; };
  if (o.comparison.json) {
    writeHeatmap(o.comparison, c);
    std::printf("{\"scene\":%s,\"vulkan\":%s,\"cpu\":%s,\"difference\":%s}\n",
                jsonQuoted(o.request.scenePath).c_str(),
                reportJson(reports[0]).c_str(), reportJson(reports[1]).c_str(),
                diffReportJson(c.diff, c.flip, failures).c_str());
  } else {
    std::printf("%s: vulkan %.3f s, cpu %.3f s (without writing); vulkan vs cpu:\n", o.request.scenePath.c_str(),
                total(reports[0]), total(reports[1]));
    printComparisonText(o.comparison, c, failures);
  }
  return failures.empty() ? kExitOk : kExitDiffers;
}

}  // namespace vkrt
